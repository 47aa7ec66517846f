#!/usr/bin/env python3
"""Writes a procedural outdoor sky as a latitude-longitude Radiance .hdr (RGBE, flat scanlines):
a small sun 35° up, a blue sky brightening to a pale horizon, a brown ground. Both illum
(--environment) and f3d (--hdri) read it; bench/compare_environment.sh renders models under it.
Usage: sky_hdr.py OUT.hdr [WIDTH]"""
import math
import struct
import sys


def rgbe(r, g, b):
    v = max(r, g, b)
    if v < 1e-32:
        return b"\0\0\0\0"
    m, e = math.frexp(v)
    scale = m * 256.0 / v
    return bytes((int(r * scale), int(g * scale), int(b * scale), e + 128))


def radiance(d):
    x, y, z = d
    sun = (math.cos(math.radians(35)) * math.sin(math.radians(40)), math.sin(math.radians(35)),
           math.cos(math.radians(35)) * math.cos(math.radians(40)))
    cos_sun = x * sun[0] + y * sun[1] + z * sun[2]
    if y >= 0:
        t = y ** 0.5
        sky = [0.85 * (1 - t) + 0.25 * t, 0.9 * (1 - t) + 0.45 * t, 1.0 * (1 - t) + 0.95 * t]
        sky = [1.2 * c for c in sky]
    else:
        sky = [0.30, 0.26, 0.22]
    if cos_sun > math.cos(math.radians(1.5)):
        return [400.0, 380.0, 340.0]
    glow = max(0.0, cos_sun) ** 64 * 2.0
    return [c + glow for c in sky]


def main():
    out = sys.argv[1]
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 512
    height = width // 2
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(("-Y %d +X %d\n" % (height, width)).encode())
        for j in range(height):
            theta = (j + 0.5) / height * math.pi
            row = bytearray()
            for i in range(width):
                phi = ((i + 0.5) / width - 0.5) * 2 * math.pi
                d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
                row += rgbe(*radiance(d))
            f.write(row)


if __name__ == "__main__":
    main()
