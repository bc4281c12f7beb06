#!/usr/bin/env python3
"""Writes the bundled sky, scenes/textures/sky.hdr: an analytic clear sky (python3 stdlib only).

Usage: python3 scenes/make-sky.py [OUT.hdr] [--width W]      (default 512 wide, 2:1)

The image is equirectangular as scenes/FORMAT.md's `environment` reads it: +Y up, the first
row straight up, u = angle around +Y from +X toward +Z over 2 pi, v = 0.5 + asin(y) / pi.
The model is a gradient plus a sun, smooth enough to be looked up filtered or not:
- sky (y >= 0): zenith blue blending to a pale horizon, (1 - y)^4 weighting the horizon;
- a glow around the sun, exp(-angle / 0.25), and a sun disc of 3 degrees radius;
- ground (y < 0): a warm grey darkening below the horizon.
Values are linear radiance, written as Radiance RGBE with run-length encoded scanlines.
"""
import math
import struct
import sys

SUN_AZIMUTH = math.radians(215.0)  # around +Y from +X toward +Z
SUN_ELEVATION = math.radians(35.0)
ZENITH = (0.18, 0.36, 0.85)
HORIZON = (0.75, 0.85, 1.0)
GROUND = (0.30, 0.27, 0.22)
SUN_GLOW = (1.2, 1.0, 0.7)
SUN_DISC = (12.0, 11.0, 9.0)
SUN_RADIUS = math.radians(3.0)


def direction(u, v):
    phi = 2.0 * math.pi * u
    theta = math.pi * (v - 0.5)  # elevation
    return (math.cos(theta) * math.cos(phi), math.sin(theta), math.cos(theta) * math.sin(phi))


SUN = direction(SUN_AZIMUTH / (2.0 * math.pi), 0.5 + SUN_ELEVATION / math.pi)


def radiance(d):
    y = d[1]
    if y < 0.0:
        k = 1.0 - 0.5 * min(1.0, -y * 3.0)
        c = [GROUND[i] * k for i in range(3)]
    else:
        h = (1.0 - y) ** 4
        c = [ZENITH[i] * (1.0 - h) + HORIZON[i] * h for i in range(3)]
    cosine = max(-1.0, min(1.0, sum(d[i] * SUN[i] for i in range(3))))
    angle = math.acos(cosine)
    glow = math.exp(-angle / 0.25) * (1.0 if y >= 0.0 else max(0.0, 1.0 + y * 5.0))
    c = [c[i] + SUN_GLOW[i] * glow for i in range(3)]
    if angle < SUN_RADIUS:
        c = [c[i] + SUN_DISC[i] for i in range(3)]
    return c


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return (0, 0, 0, 0)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return (int(c[0] * scale), int(c[1] * scale), int(c[2] * scale), exponent + 128)


def rle(values):
    """One channel of a scanline in Radiance's run-length encoding."""
    out = bytearray()
    i, n = 0, len(values)
    while i < n:
        run = 1
        while i + run < n and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 4:
            out += bytes((128 + run, values[i]))
            i += run
            continue
        j = i  # literal stretch up to the next run of 4 or more
        while j < n and j - i < 128:
            if j + 3 < n and values[j] == values[j + 1] == values[j + 2] == values[j + 3]:
                break
            j += 1
        out += bytes((j - i,)) + bytes(values[i:j])
        i = j
    return out


def main(argv):
    out, width = "sky.hdr", 512
    args = argv[1:]
    while args:
        if args[0] == "--width" and len(args) > 1 and args[1].isdigit() and 8 <= int(args[1]) <= 32767:
            width = int(args[1])
            args = args[2:]
        elif not args[0].startswith("-"):
            out = args[0]
            args = args[1:]
        else:
            print("make-sky.py: bad argument %r (expected OUT.hdr or --width W, 8 to 32767)" % args[0],
                  file=sys.stderr)
            return 2
    height = width // 2
    data = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
    for row in range(height):
        v = 1.0 - (row + 0.5) / height  # first row straight up
        pixels = [rgbe(radiance(direction((col + 0.5) / width, v))) for col in range(width)]
        data += struct.pack(">BBH", 2, 2, width)
        for channel in range(4):
            data += rle([p[channel] for p in pixels])
    with open(out, "wb") as f:
        f.write(data)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
