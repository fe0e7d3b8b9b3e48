#!/usr/bin/env python3
# Compares two 8-bit RGB/RGBA PNGs over the pixels either one drew (a pixel equal to its own
# image's top-left corner is background): prints the count and the max, 99th percentile and
# mean difference in 8-bit levels, and exits 1 when the coverage differs by more than
# --coverage (fraction) or the p99/max differences exceed --p99/--max. Standard library only
# (zlib), so the tests need no imaging package.
# Usage: png_compare.py A.png B.png [--coverage 0.01] [--p99 2] [--max 8]
import argparse
import struct
import sys
import zlib


def load(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    at, idat, width, height, channels = 8, b"", 0, 0, 0
    while at < len(data):
        size, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at + 8:at + 8 + size]
        at += 12 + size
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            if depth != 8 or colour not in (2, 6) or chunk[12] != 0:
                sys.exit(f"{path}: only 8-bit non-interlaced RGB/RGBA")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += chunk
    raw, stride = zlib.decompress(idat), width * channels
    pixels, prev, pos = bytearray(), bytearray(stride), 0
    for _ in range(height):
        kind, row = raw[pos], bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for x in range(stride):
            a = row[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if kind == 1:
                row[x] = (row[x] + a) & 255
            elif kind == 2:
                row[x] = (row[x] + b) & 255
            elif kind == 3:
                row[x] = (row[x] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        pixels += row
        prev = row
    return width, height, channels, pixels


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--coverage", type=float, default=0.01)
    ap.add_argument("--p99", type=float, default=2)
    ap.add_argument("--max", type=float, default=8)
    args = ap.parse_args()
    wa, ha, ca, A = load(args.a)
    wb, hb, cb, B = load(args.b)
    if (wa, ha) != (wb, hb):
        print(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
        return 1
    drawn_a = drawn_b = 0
    diffs = []
    for i in range(wa * ha):
        pa, pb = A[i * ca:i * ca + 3], B[i * cb:i * cb + 3]
        da, db = pa != A[:3], pb != B[:3]
        drawn_a += da
        drawn_b += db
        if da and db:
            diffs.append(max(abs(pa[k] - pb[k]) for k in range(3)))
    if not diffs:
        print("neither image drew anything both share")
        return 1
    diffs.sort()
    p99, worst, mean = diffs[int(0.99 * (len(diffs) - 1))], diffs[-1], sum(diffs) / len(diffs)
    coverage = abs(drawn_a - drawn_b) / max(drawn_a, drawn_b)
    print(f"drawn {drawn_a} / {drawn_b} pixels (coverage differs by {coverage:.4f}); "
          f"difference max {worst}, p99 {p99}, mean {mean:.3f} levels")
    ok = coverage <= args.coverage and p99 <= args.p99 and worst <= args.max
    print("images match" if ok else "images differ")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
