#!/usr/bin/env python3
"""Writes scenes/textures/tiles.png (64 x 64, 8-bit sRGB, python3 stdlib only): a smooth
colour ramp (red along u, green along v) with a dark cross, so that a texture's orientation,
scale and offset are all visible in a render and in its POV-Ray twin.

Usage: python3 scenes/textures/make-tiles.py [OUT.png]
"""
import struct
import sys
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)


def main(argv):
    out = argv[1] if len(argv) > 1 else "tiles.png"
    size = 64
    rows = bytearray()
    for y in range(size):
        rows.append(0)  # filter: none
        for x in range(size):
            r, g, b = 40 + 200 * x // (size - 1), 40 + 200 * (size - 1 - y) // (size - 1), 120
            if 28 <= x < 36 or 28 <= y < 36:
                r, g, b = 30, 30, 40
            rows += bytes((r, g, b))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    with open(out, "wb") as f:
        f.write(png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
