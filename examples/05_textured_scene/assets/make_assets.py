#!/usr/bin/env python3
"""Writes this example's assets, made here (CC0, see LICENSE.txt): torus.obj, a torus of 24 x 12
quads with positions and texture coordinates but no normals (the loader computes smooth ones), and
ground.png, 64x64 RGB: 8 x 8 stone tiles of 7 x 7 texels, two colours in a checker, with a
1-texel grout line on each tile's low edges. Run it from this folder; it needs only Python."""
import math
import struct
import zlib

MAJOR, MINOR, RINGS, SIDES = 1.0, 0.35, 24, 12

def torus():
    lines = ["# A torus made by make_assets.py for examples/05_textured_scene; CC0 (LICENSE.txt).",
             "# No vn lines: proceduray::load_obj computes smooth, angle-weighted normals."]
    for i in range(RINGS + 1):
        u = 2 * math.pi * i / RINGS
        for j in range(SIDES + 1):
            v = 2 * math.pi * j / SIDES
            r = MAJOR + MINOR * math.cos(v)
            lines.append("v %.6f %.6f %.6f" % (r * math.cos(u), MINOR * math.sin(v), -r * math.sin(u)))
    for i in range(RINGS + 1):
        for j in range(SIDES + 1):
            lines.append("vt %.6f %.6f" % (i / RINGS, j / SIDES))
    for i in range(RINGS):
        for j in range(SIDES):
            a = i * (SIDES + 1) + j + 1
            b = (i + 1) * (SIDES + 1) + j + 1
            lines.append("f %d/%d %d/%d %d/%d %d/%d" % (a, a, b, b, b + 1, b + 1, a + 1, a + 1))
    return "\n".join(lines) + "\n"

TILE, GROUT = 8, (40, 36, 32)
STONES = [(196, 170, 130), (120, 130, 150)]

def ground_texel(x, y):
    if x % TILE == 0 or y % TILE == 0:
        return GROUT
    return STONES[(x // TILE + y // TILE) % 2]

def png(width, height, texel):
    rows = b"".join(b"\x00" + bytes(c for x in range(width) for c in texel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")

if __name__ == "__main__":
    with open("torus.obj", "w") as f:
        f.write(torus())
    with open("ground.png", "wb") as f:
        f.write(png(64, 64, ground_texel))
