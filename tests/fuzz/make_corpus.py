#!/usr/bin/env python3
"""Writes the fuzzer's seed corpus (tests/fuzz/corpus/): valid packets of the documented format
(firmware/README.md), alone, in a row, around garbage, with a fake header, a flipped bit and a
sequence gap. The CRC is zlib's, independent of the code under test. Run from anywhere."""
import os
import random
import struct
import zlib


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


def main():
    corpus = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    os.makedirs(corpus, exist_ok=True)
    flipped = bytearray(packet(1))
    flipped[40] ^= 0x08
    seeds = {
        "one_packet_n2.bin": packet(0, n=2),
        "two_packets_n16.bin": packet(0, n=16) + packet(1, n=16),
        "garbage_around_packets.bin": garbage(13, 1) + packet(0) + garbage(40, 2) + packet(1) + garbage(5, 3),
        "fake_header_then_packets.bin": b"EM\x01\x10\x0c\x04\x00\x02" + bytes(8) + packet(0) + packet(1),
        "flipped_bit.bin": packet(0) + bytes(flipped) + packet(2),
        "sequence_gap_and_wrap.bin": packet(0xFFFFFFFE, n=2) + packet(0xFFFFFFFF, n=2) + packet(3, n=2),
        "ten_bit_n8.bin": packet(0, n=8, bits=10, oversampling=1) + packet(1, n=8, bits=10, oversampling=1),
        "truncated_then_packet.bin": packet(0, n=8)[:70] + packet(1, n=8),
    }
    for name, data in seeds.items():
        with open(os.path.join(corpus, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
