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
        "linear_force_law.json": text({"a1": 0.8, "a2": 1.5, "a3": 0.02,
                                       "force_law": {"b1_V_mm2": 12.5, "b2": -0.02, "b3": -0.84, "log_std": 0.03,
                                                     "indenter_radius_mm": 5}}),
        "broken_force_law.json": text({"a1": 0.8, "a2": 1.5, "a3": 0.02, "force_law": {"b1_V_mm2": 1, "b3": 0.5}}),
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


def stl_ascii(triangles, name="sheet", indent=True):
    pad = (lambda k: " " * k) if indent else (lambda k: "")
    out = "solid %s\n" % name
    for t in triangles:
        out += pad(1) + "facet normal 0 0 1\n" + pad(2) + "outer loop\n"
        out += "".join(pad(3) + "vertex %s %s %s\n" % tuple(v) for v in t)
        out += pad(2) + "endloop\n" + pad(1) + "endfacet\n"
    return (out + "endsolid %s\n" % name).encode()


def stl_binary(triangles, header=b"binary STL from make_corpus.py"):
    out = header.ljust(80, b" ")[:80] + struct.pack("<I", len(triangles))
    for t in triangles:
        out += struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *v) for v in t) + b"\0\0"
    return out


def square_grid(n, size_mm, z=lambda x, y: 0.0):
    """n × n squares of a size_mm sheet, two triangles each, counter-clockwise from +z."""
    h = size_mm / n
    p = lambda i, j: (i * h, j * h, z(i * h, j * h))
    tris = []
    for i in range(n):
        for j in range(n):
            tris += [(p(i, j), p(i + 1, j), p(i + 1, j + 1)), (p(i, j), p(i + 1, j + 1), p(i, j + 1))]
    return tris


def stl_file_seeds():
    """What an STL sheet's file is (README "Sensor description": ASCII or binary), and the mistakes
    emit refuses before Gmsh reads it (mesh/stl_file_check.hpp)."""
    grid = square_grid(4, 20)
    dome = square_grid(6, 12, z=lambda x, y: 5 - 0.02 * ((x - 6) ** 2 + (y - 6) ** 2))
    nan = [list(t) for t in grid]
    nan[0] = [("nan", 0, 0)] + list(grid[0][1:])
    collinear = list(grid) + [((0, 0, 0), (1, 1, 0), (2, 2, 0))]
    two_solids = stl_ascii(grid[:8], "a") + stl_ascii(grid[8:], "b")
    big_header = stl_binary(grid[:2])[:80] + struct.pack("<I", 1200000) + stl_binary(grid[:2])[84:]
    return {
        "ascii_grid.stl": stl_ascii(grid),
        "ascii_dome_unindented.stl": stl_ascii(dome, indent=False),
        "ascii_crlf_uppercase.stl": stl_ascii(grid[:4]).replace(b"\n", b"\r\n").upper(),
        "ascii_two_solids.stl": two_solids,
        "ascii_no_endsolid.stl": stl_ascii(grid[:3]).replace(b"endsolid sheet\n", b""),
        "binary_grid.stl": stl_binary(grid),
        "binary_dome.stl": stl_binary(dome),
        "binary_header_says_solid.stl": stl_binary(grid[:6], header=b"solid exported by a CAD tool"),
        "broken_nan_vertex.stl": stl_ascii(nan),
        "broken_zero_area.stl": stl_ascii(collinear),
        "broken_binary_nan.stl": stl_binary([((float("nan"), 0, 0), (1, 0, 0), (0, 1, 0))] + grid[:2]),
        "broken_binary_count_1200000.stl": big_header,
        "broken_binary_cut_short.stl": stl_binary(grid)[:-7],
        "broken_blank_line.stl": stl_ascii(grid[:2]).replace(b"endfacet\n", b"endfacet\n\n", 1),
        "broken_long_line.stl": stl_ascii(grid[:2]).replace(b"vertex 0.0", b"vertex 0." + b"0" * 300, 1),
        "broken_empty_solid.stl": b"solid empty\nendsolid empty\n",
        "broken_empty.stl": b"",
    }


def msh41_ascii(nodes, triangles, lines=()):
    """A .msh 4.1 ASCII file: the nodes on one surface, its triangles, and 2-node lines."""
    out = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 %d 1 %d\n2 1 0 %d\n" % (len(nodes), len(nodes), len(nodes))
    out += "".join("%d\n" % (k + 1) for k in range(len(nodes)))
    out += "".join("%r %r %r\n" % tuple(p) for p in nodes) + "$EndNodes\n"
    blocks = [(2, 1, 2, triangles)] + ([(1, 1, 1, lines)] if lines else [])
    out += "$Elements\n%d %d 1 %d\n" % (len(blocks), len(triangles) + len(lines), len(triangles) + len(lines))
    tag = 1
    for dim, entity, kind, elements in blocks:
        out += "%d %d %d %d\n" % (dim, entity, kind, len(elements))
        for e in elements:
            out += "%d %s\n" % (tag, " ".join(str(v + 1) for v in e))
            tag += 1
    return (out + "$EndElements\n").encode()


def msh41_binary(nodes, triangles):
    n = len(nodes)
    out = b"$MeshFormat\n4.1 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n$Nodes\n"
    out += struct.pack("<4Q", 1, n, 1, n) + struct.pack("<3iQ", 2, 1, 0, n)
    out += struct.pack("<%dQ" % n, *range(1, n + 1)) + b"".join(struct.pack("<3d", *p) for p in nodes)
    out += b"\n$EndNodes\n$Elements\n" + struct.pack("<4Q", 1, len(triangles), 1, len(triangles))
    out += struct.pack("<3iQ", 2, 1, 2, len(triangles))
    out += b"".join(struct.pack("<4Q", k + 1, *(v + 1 for v in t)) for k, t in enumerate(triangles))
    return out + b"\n$EndElements\n"


def msh22(nodes, triangles, binary=False):
    if not binary:
        out = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes)
        out += "".join("%d %r %r %r\n" % ((k + 1,) + tuple(p)) for k, p in enumerate(nodes))
        out += "$EndNodes\n$Elements\n%d\n" % len(triangles)
        out += "".join("%d 2 2 1 1 %s\n" % (k + 1, " ".join(str(v + 1) for v in t)) for k, t in enumerate(triangles))
        return (out + "$EndElements\n").encode()
    out = b"$MeshFormat\n2.2 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes)
    out += b"".join(struct.pack("<i3d", k + 1, *p) for k, p in enumerate(nodes))
    out += b"\n$EndNodes\n$Elements\n%d\n" % len(triangles) + struct.pack("<3i", 2, len(triangles), 2)
    out += b"".join(struct.pack("<6i", k + 1, 1, 1, *(v + 1 for v in t)) for k, t in enumerate(triangles))
    return out + b"\n$EndElements\n"


def msh_file_seeds():
    """Gmsh's .msh 4.1 and 2.2, ASCII and binary (Gmsh's reference manual, "MSH file format"), and
    the mistakes emit refuses before Gmsh reads it (mesh/msh_file_check.hpp)."""
    n = 3
    nodes = [(i * 10.0 / n, j * 10.0 / n, 0.0) for j in range(n + 1) for i in range(n + 1)]
    at = lambda i, j: j * (n + 1) + i
    tris = [t for i in range(n) for j in range(n)
            for t in ((at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1)))]
    border = [(at(i, 0), at(i + 1, 0)) for i in range(n)]
    named = msh41_ascii(nodes, tris, border).replace(
        b"$Nodes", b"$PhysicalNames\n1\n1 1 \"electrode 0\"\n$EndPhysicalNames\n$Nodes", 1)
    nan = list(nodes)
    nan[5] = (float("nan"), nan[5][1], 0.0)
    return {
        "v41_ascii.msh": msh41_ascii(nodes, tris),
        "v41_ascii_lines_names.msh": named,
        "v41_binary.msh": msh41_binary(nodes, tris),
        "v22_ascii.msh": msh22(nodes, tris),
        "v22_binary.msh": msh22(nodes, tris, binary=True),
        "broken_nan_node.msh": msh41_ascii(nan, tris),
        "broken_count_1200000.msh": msh41_ascii(nodes, tris).replace(b"2 1 2 18\n", b"2 1 2 1200000\n"),
        "broken_nodes_1e12.msh": msh41_ascii(nodes, tris).replace(b"1 16 1 16\n", b"1 1000000000000 1 16\n"),
        "broken_cut_short.msh": msh41_ascii(nodes, tris)[:-60],
        "broken_v40.msh": msh41_ascii(nodes, tris).replace(b"4.1 0 8", b"4 0 8"),
        "broken_unknown_type.msh": msh22(nodes, tris).replace(b" 2 2 1 1 ", b" 99 2 1 1 ", 1),
        "broken_empty.msh": b"",
    }


def excitation_json_seeds():
    """The first byte is the electrode count − 3 (excitation_json_fuzz.cpp), the rest the block."""
    def seed(electrodes, block):
        return bytes([electrodes - 3]) + (block if isinstance(block, bytes) else json.dumps(block).encode())

    return {
        "adjacent_n16.json": seed(16, {"drive": "adjacent", "measure": "adjacent", "current_A": 0.001}),
        "opposite_skip_n8.json": seed(8, {"drive": "opposite", "skip_driving_electrodes": True}),
        "skip2_lists_n8.json": seed(8, {"drive": "skip-2", "measure": [[1, 0], [3, 2]],
                                        "contact_impedance_ohm_mm": [1, 2, 3, 4, 5, 6, 7, 8]}),
        "pairs_readings_n8.json": seed(8, {"drive": [[0, 4], [2, 6]], "readings": [[1, 3, 2], [0, 5, 1]],
                                           "frequency_Hz": 1000}),
        "one_impedance_n32.json": seed(32, {"drive": "skip-4", "contact_impedance_ohm_mm": 50}),
        "broken_pattern.json": seed(8, {"drive": "diagonal"}),
        "broken_electrode_9_of_8.json": seed(8, {"drive": [[0, 9]]}),
        "broken_same_electrode.json": seed(8, {"drive": [[3, 3]]}),
        "broken_both_lists.json": seed(8, {"drive": "adjacent", "readings": [[0, 1, 2]], "measure": "adjacent"}),
        "broken_no_reading.json": seed(3, {"drive": "adjacent", "measure": [[1, 0]], "skip_driving_electrodes": True}),
        "broken_impedance_count.json": seed(8, {"drive": "adjacent", "contact_impedance_ohm_mm": [1, 2]}),
        "broken_reading_drive.json": seed(8, {"drive": "adjacent", "readings": [[8, 1, 2]]}),
        "broken_not_object.json": seed(8, [1, 2, 3]),
        "broken_big_number.json": seed(8, b'{"drive": "adjacent", "current_A": 1e999}'),
    }


def main():
    targets = {
        "packet_decoder_fuzz": packet_decoder_seeds(),
        "sensor_json_fuzz": sensor_json_seeds(),
        "frames_csv_fuzz": frames_csv_seeds(),
        "presses_csv_fuzz": presses_csv_seeds(),
        "calibration_json_fuzz": calibration_json_seeds(),
        "recording_fuzz": recording_seeds(),
        "stl_file_fuzz": stl_file_seeds(),
        "msh_file_fuzz": msh_file_seeds(),
        "excitation_json_fuzz": excitation_json_seeds(),
    }
    for target, seeds in targets.items():
        corpus = os.path.join(HERE, "corpus", target)
        os.makedirs(corpus, exist_ok=True)
        for name, data in seeds.items():
            with open(os.path.join(corpus, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
