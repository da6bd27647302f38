#!/usr/bin/env python3
"""compareStates.py <serial demState> <parallel demState>: exit 0 when every array of the two
rockfrac state files (libs/io/stateFile.cpp: magic, version, count, then per array its name,
type and values, then a checksum) is byte-identical, except the energies, the force rates and
the initial balance (sums over ranks in a decomposed run), which must agree within 1e-12 of
the largest value of their array. Prints the arrays that differ."""
import struct
import sys

TYPES = {1: ("d", 8), 2: ("q", 8), 3: ("B", 1)}
SUMMED = {"energies", "energyExchanged", "forceRates", "initialBalance"}


def read(path):
    data = open(path, "rb").read()
    at = 8  # magic
    version, count = struct.unpack_from("<II", data, at)
    at += 8
    arrays = {}
    for _ in range(count):
        (length,) = struct.unpack_from("<I", data, at)
        at += 4
        name = data[at:at + length].decode()
        at += length
        code, n = struct.unpack_from("<BQ", data, at)
        at += 9
        fmt, size = TYPES[code]
        arrays[name] = (fmt, data[at:at + n * size])
        at += n * size
    return arrays


def main():
    a, b = read(sys.argv[1]), read(sys.argv[2])
    if a.keys() != b.keys():
        print("arrays differ:", sorted(a.keys() ^ b.keys()))
        return 1
    bad = 0
    for name in sorted(a):
        if a[name] == b[name]:
            continue
        fmt, raw_a = a[name]
        _, raw_b = b[name]
        if name not in SUMMED or fmt != "d" or len(raw_a) != len(raw_b):
            print(f"{name}: differs")
            bad += 1
            continue
        va = struct.unpack(f"<{len(raw_a) // 8}d", raw_a)
        vb = struct.unpack(f"<{len(raw_b) // 8}d", raw_b)
        scale = max(max(abs(x) for x in va), 1e-300)
        worst = max(abs(x - y) for x, y in zip(va, vb))
        if worst > 1e-12 * scale:
            print(f"{name}: differs by {worst:.3g} (largest value {scale:.3g})")
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
