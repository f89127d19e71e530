#!/usr/bin/env python3
"""Writes the cube STL fixtures used by tests/core/walls/mesh_io_test.cc (independently of demcal's
own writer, so the reader is not only tested against itself).

cube_10mm_ascii.stl: ASCII STL of the cube [0, 10]^3 in millimetres (12 triangles, outward
  counter-clockwise corners), volume 1000 mm^3 = 1e-6 m^3 when read with scale 0.001.
cube_binary_solid_header.stl: binary STL of the cube [1, 3] x [2, 4] x [3, 5] in metres (volume
  8 m^3) whose 80-byte header starts with "solid", as many CAD exporters write: a reader must not
  take it for ASCII.
"""
import struct

UNIT_CUBE = [  # two triangles per face, outward counter-clockwise
    ((0, 0, 0), (0, 1, 0), (1, 1, 0)), ((0, 0, 0), (1, 1, 0), (1, 0, 0)),  # z = 0
    ((0, 0, 1), (1, 0, 1), (1, 1, 1)), ((0, 0, 1), (1, 1, 1), (0, 1, 1)),  # z = 1
    ((0, 0, 0), (1, 0, 0), (1, 0, 1)), ((0, 0, 0), (1, 0, 1), (0, 0, 1)),  # y = 0
    ((0, 1, 0), (0, 1, 1), (1, 1, 1)), ((0, 1, 0), (1, 1, 1), (1, 1, 0)),  # y = 1
    ((0, 0, 0), (0, 0, 1), (0, 1, 1)), ((0, 0, 0), (0, 1, 1), (0, 1, 0)),  # x = 0
    ((1, 0, 0), (1, 1, 0), (1, 1, 1)), ((1, 0, 0), (1, 1, 1), (1, 0, 1)),  # x = 1
]


def normal(t):
    a, b, c = t
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = sum(x * x for x in n) ** 0.5
    return [x / length for x in n]


def transform(t, scale, offset):
    return tuple(tuple(scale * p[i] + offset[i] for i in range(3)) for p in t)


with open("cube_10mm_ascii.stl", "w", newline="\n") as f:
    f.write("solid cube_10mm\n")
    for t in UNIT_CUBE:
        tt = transform(t, 10.0, (0, 0, 0))
        f.write("  facet normal %g %g %g\n    outer loop\n" % tuple(normal(t)))
        for p in tt:
            f.write("      vertex %.6e %.6e %.6e\n" % p)
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid cube_10mm\n")

with open("cube_binary_solid_header.stl", "wb") as f:
    f.write(b"solid cube exported with a misleading binary header".ljust(80, b" "))
    f.write(struct.pack("<I", len(UNIT_CUBE)))
    for t in UNIT_CUBE:
        f.write(struct.pack("<3f", *normal(t)))
        for p in transform(t, 2.0, (1, 2, 3)):
            f.write(struct.pack("<3f", *p))
        f.write(struct.pack("<H", 0))
