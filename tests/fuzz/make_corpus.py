#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora, tests/fuzz/corpus/<target>/: small valid files of each
format and a few broken ones, from the formats' documentation (README "Files", docs/recording.md,
firmware/README.md), independent of the code under test (the CRC is zlib's). Run from anywhere.

packet_decoder_fuzz: valid packets alone, in a row, around garbage, with a fake header, a flipped
bit and a sequence gap. The parsers' targets: see their functions below."""
import json
import math
import os
import random
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples", "sensors")


def packet(sequence, n=4, bits=12, oversampling=4, timestamp_us=None, seed=0):
    rng = random.Random(seed * 1000 + sequence)
    counts = [rng.randrange(1 << bits) for _ in range(n * n)]
    body = struct.pack("<BBBBHII", 1, n, bits, oversampling, 2 * n * n, sequence,
                       (1000 + 20000 * sequence) % (1 << 32) if timestamp_us is None else timestamp_us)
    body += struct.pack("<%dH" % (n * n), *counts)
    return b"EM" + body + struct.pack("<I", zlib.crc32(body))


def garbage(count, seed):
    rng = random.Random(seed)
    return bytes(rng.randrange(256) for _ in range(count))


def packet_decoder_seeds():
    flipped = bytearray(packet(1))
    flipped[40] ^= 0x08
    return {
        "one_packet_n2.bin": packet(0, n=2),
        "two_packets_n16.bin": packet(0, n=16) + packet(1, n=16),
        "garbage_around_packets.bin": garbage(13, 1) + packet(0) + garbage(40, 2) + packet(1) + garbage(5, 3),
        "fake_header_then_packets.bin": b"EM\x01\x10\x0c\x04\x00\x02" + bytes(8) + packet(0) + packet(1),
        "flipped_bit.bin": packet(0) + bytes(flipped) + packet(2),
        "sequence_gap_and_wrap.bin": packet(0xFFFFFFFE, n=2) + packet(0xFFFFFFFF, n=2) + packet(3, n=2),
        "ten_bit_n8.bin": packet(0, n=8, bits=10, oversampling=1) + packet(1, n=8, bits=10, oversampling=1),
        "truncated_then_packet.bin": packet(0, n=8)[:70] + packet(1, n=8),
    }


def text(value):
    return (value if isinstance(value, str) else json.dumps(value, indent=2) + "\n").encode()


def sensor_json_seeds():
    """The example sensors, each shape and electrode form, and broken ones."""
    seeds = {}
    for name in sorted(n for n in os.listdir(EXAMPLES) if n.endswith(".json")):
        with open(os.path.join(EXAMPLES, name), "rb") as f:
            seeds["example_" + name] = f.read()
    electrodes = [{"x_mm": x, "y_mm": y, "width_mm": 2} for x, y in
                  [(7.5, 0), (22.5, 0), (30, 7.5), (30, 22.5), (22.5, 30), (7.5, 30), (0, 22.5), (0, 7.5)]]
    seeds.update({
        "electrode_list.json": text({"shape": {"type": "rectangle", "width_mm": 30, "height_mm": 30},
                                     "electrodes": electrodes, "adc": {"bits": 16, "vref_V": 5, "noise_V": 0}}),
        "circle_default_center.json": text({"shape": {"type": "circle", "radius_mm": 10},
                                            "electrodes": {"count": 8, "width_mm": 1}}),
        "mesh_file.json": text({"name": "from a mesh", "shape": {"type": "mesh", "file": "sheet.msh"},
                                "mesh": {"element_size_mm": 2, "twin_refinement": 1.5}}),
        "triangle.json": text({"shape": {"type": "polygon", "points_mm": [[0, 0], [40, 0], [20, 30]]},
                               "electrodes": {"count": 6, "width_mm": 2},
                               "contact_law": {"gamma": -1.5, "min_pressure_N_per_mm2": 0}}),
        "excitation_lists.json": text({"shape": {"type": "circle", "radius_mm": 40},
                                       "electrodes": {"count": 8, "width_mm": 2},
                                       "excitation": {"drive": [[0, 4], [2, 6]], "measure": [[1, 0], [3, 2]],
                                                      "skip_driving_electrodes": True,
                                                      "contact_impedance_ohm_mm": [1, 2, 3, 4, 5, 6, 7, 8]}}),
        "excitation_readings.json": text({"shape": {"type": "circle", "radius_mm": 40},
                                          "electrodes": {"count": 8, "width_mm": 2},
                                          "excitation": {"drive": "skip-2", "readings": [[7, 3, 2], [0, 5, 1]]}}),
        "broken_excitation.json": text({"shape": {"type": "circle", "radius_mm": 40},
                                        "electrodes": {"count": 8, "width_mm": 2},
                                        "excitation": {"drive": [[0, 9]], "measure": "diagonal"}}),
        "broken_truncated.json": b'{"shape": {"type": "rectangle", "width_mm": 60, "height_mm"',
        "broken_unknown_key.json": text({"shape": {"type": "rectangle", "width_mm": 60, "height_mm": 60},
                                         "electrodes": {"count": 16, "width_mm": 3}, "colour": "red"}),
        "broken_self_crossing.json": text({"shape": {"type": "polygon", "points_mm": [[0, 0], [10, 10], [10, 0],
                                                                                      [0, 10]]},
                                           "electrodes": {"count": 4, "width_mm": 1}}),
        "broken_electrode_off_border.json": text({"shape": {"type": "rectangle", "width_mm": 30, "height_mm": 30},
                                                  "electrodes": [{"x_mm": 15, "y_mm": 15, "width_mm": 2}]}),
        "broken_wide_electrodes.json": text({"shape": {"type": "rectangle", "width_mm": 10, "height_mm": 10},
                                             "electrodes": {"count": 64, "width_mm": 3}}),
        "broken_big_number.json": b'{"shape": {"type": "rectangle", "width_mm": 1e999, "height_mm": 60}}\n',
        "broken_empty.json": b"",
        # Once a stack overflow: the error message dumped the value, recursing once per level.
        "broken_deep_name.json": b'{"name": ' + b"[" * 30000 + b"]" * 30000 + b"}",
    })
    return seeds


def frames_line(values):
    return ",".join("%.7f" % v for v in values) + "\n"


def frames_csv_seeds():
    """The first byte is the electrode count − 3 (frames_csv_fuzz.cpp), the rest the file."""
    rng = random.Random(7)

    def frames(n, count, **kw):
        return bytes([n - 3]) + "".join(frames_line(rng.uniform(0, 3.3) for _ in range(n * n))
                                        for _ in range(count)).encode()

    return {
        "n4_two_frames.csv": frames(4, 2),
        "n16_one_frame.csv": frames(16, 1),
        "n8_three_frames.csv": frames(8, 3),
        "n16_sixteen_frames.csv": frames(16, 16),  # ~45 KB: libFuzzer's length limit starts there
        "n3_blank_lines_crlf_spaces.csv": bytes([0]) + b"\r\n" + b" 1.5, 2,3 ,4e-1,-5,6.25,7,8,9\r\n\t\n" +
                                          b"0,0,0,0,0,0,0,0,0",
        "n3_hex_and_exponents.csv": bytes([0]) + b"0x1p-3,1E+2,.5,5.,+1,-0,1e-300,2,3\n",
        "broken_n4_too_few.csv": bytes([1]) + b"1,2,3\n",
        "broken_n3_nan.csv": bytes([0]) + b"1,2,nan,4,5,6,7,8,9\n",
        "broken_n3_inf_overflow.csv": bytes([0]) + b"1,2,1e999,4,5,6,7,8,9\n",
        "broken_n3_text.csv": bytes([0]) + b"1,2,volts,4,5,6,7,8,9\n",
        "broken_n3_empty_field.csv": bytes([0]) + b"1,2,,4,5,6,7,8,9\n",
        # Read as one frame today, the text after the NUL byte ignored (the parser stops at the
        # line's c_str() end); for src/io/frames_csv.cpp's rewrite to reject.
        "accepted_n3_nul_ends_line.csv": bytes([0]) + b"1,2,3,4,5,6,7,8,9\0,garbage\n",
    }


def presses_csv_seeds():
    header = "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n"

    def row(frame, x, y, r, force):
        return "%d,%.4f,%.4f,%.4f,%.6f,%.6f\n" % (frame, x, y, r, force, force / (math.pi * r * r))

    return {
        "one_press.csv": (header + row(0, 30, 30, 5, 10)).encode(),
        "grid_with_empty_frames.csv": (header + row(0, 10, 10, 4, 5) + row(2, 20, 10, 4, 5) +
                                       row(5, 50, 50, 4, 5)).encode(),
        "two_fingers.csv": (header + row(0, 20, 30, 5, 8) + row(0, 40, 30, 5, 12) + row(1, 22, 30, 5, 8)).encode(),
        "grid_thousand_rows.csv": (header + "".join(row(k, 5 + k % 50, 5 + k // 50, 4, 1 + k % 39)
                                                    for k in range(1000))).encode(),  # ~45 KB
        "header_only_crlf.csv": header.replace("\n", "\r\n").encode(),
        "old_header_five_columns.csv": b"frame,x_mm,y_mm,radius_mm,force_N\n0,1,2,3,4\n\n1,5,6,7,8\n",
        "broken_no_header.csv": b"0,30,30,5,10\n",
        "broken_negative_frame.csv": (header + "-1,30,30,5,10,0.1\n").encode(),
        "broken_short_row.csv": (header + "0,30,30\n").encode(),
        "broken_empty.csv": b"",
        # Findings of presses_csv_fuzz, open until src/io/presses_csv.cpp bounds the frame index:
        # the row's frame index sizes the sequence, so 2^63 − 1 (strtol saturates there) throws
        # std::length_error, and 10^8 asks for 2.4 GB from a 50-byte file.
        "finding_frame_index_saturates.csv": (header + "9223372036854775807,1,1,3,4,0.1\n").encode(),
        "finding_frame_index_allocates.csv": (header + "100000000,1,1,3,4,0.1\n").encode(),
        # Read today without complaint: NaN and infinite coordinates, a negative radius and force.
        "accepted_nan_negative.csv": (header + "0,nan,inf,-3,-4,0.1\n").encode(),
    }


def calibration_json_seeds():
    sheet = {"box_mm": [0, 0, 60, 60], "log_conductance": [0.01, -0.02, 0.03, 0.0, -0.01]}
    return {
        "linear.json": text({"a1": 0.8, "a2": 1.5, "a3": 0.02}),
        "fit.json": text({"alpha_ohm_mm2": 2.0e5, "gamma": -1.2}),
        "fit_indenter_sheet.json": text({"alpha_ohm_mm2": 1.9e5, "gamma": -1.1, "indenter_radius_mm": 4,
                                         "sheet_correction": sheet}),
        "broken_mixed_kinds.json": text({"a1": 1, "a2": 1, "a3": 1, "gamma": -1}),
        "broken_missing_a3.json": text({"a1": 1, "a2": 1}),
        "broken_positive_gamma.json": text({"alpha_ohm_mm2": 1, "gamma": 1}),
        "broken_sheet_box.json": text({"alpha_ohm_mm2": 1, "gamma": -1,
                                       "sheet_correction": {"box_mm": [60, 0, 0, 60], "log_conductance": [1, 2]}}),
        "broken_array.json": b"[1, 2, 3]\n",
        "broken_big_number.json": b'{"a1": 1e400, "a2": 1, "a3": 1}\n',
        "broken_truncated.json": b'{"a1": 0.8, "a2": ',
    }


def recording_header(n=16, bits=12, vref=3.3, version=1, header_size=32, magic=b"EMITREC1"):
    return magic + struct.pack("<HHHHdQ", version, header_size, n, bits, vref, 1764000000000000)


def recording_seeds():
    """recording_fuzz reads with the default sensor: 16 electrodes."""
    bad_crc = bytearray(packet(1, n=16))
    bad_crc[100] ^= 0x01
    return {
        "three_frames_n16.emitrec": recording_header() + b"".join(packet(k, n=16) for k in range(3)),
        "timestamp_wrap_n16.emitrec": recording_header(bits=16, vref=5.0) +
                                      packet(0, n=16, bits=16, timestamp_us=0xFFFFF000) +
                                      packet(1, n=16, bits=16, timestamp_us=0x00000100),
        "forty_frames_n16.emitrec": recording_header() + b"".join(packet(k, n=16, seed=2) for k in range(40)),
        "header_only.emitrec": recording_header(),
        "broken_truncated.emitrec": recording_header() + packet(0, n=16) + packet(1, n=16)[:200],
        "broken_crc.emitrec": recording_header() + packet(0, n=16) + bytes(bad_crc) + packet(2, n=16),
        "broken_n8_for_n16.emitrec": recording_header(n=8) + packet(0, n=8),
        "broken_packet_n8_in_n16.emitrec": recording_header() + packet(0, n=8) + bytes(532 - 148),
        "broken_version.emitrec": recording_header(version=2) + packet(0, n=16),
        "broken_vref_nan.emitrec": recording_header(vref=float("nan")) + packet(0, n=16),
        "broken_magic.emitrec": recording_header(magic=b"EMITREC0") + packet(0, n=16),
    }


def main():
    targets = {
        "packet_decoder_fuzz": packet_decoder_seeds(),
        "sensor_json_fuzz": sensor_json_seeds(),
        "frames_csv_fuzz": frames_csv_seeds(),
        "presses_csv_fuzz": presses_csv_seeds(),
        "calibration_json_fuzz": calibration_json_seeds(),
        "recording_fuzz": recording_seeds(),
    }
    for target, seeds in targets.items():
        corpus = os.path.join(HERE, "corpus", target)
        os.makedirs(corpus, exist_ok=True)
        for name, data in seeds.items():
            with open(os.path.join(corpus, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
