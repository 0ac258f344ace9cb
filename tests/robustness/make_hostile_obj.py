#!/usr/bin/env python3
"""Writes the large hostile OBJ files the robustness tests need, which are
too big to keep in the repository:

  make_hostile_obj.py soup OUT      3000 random triangles piercing each other
                                    (once 59 s and 9.6 GB in the BSP build)
  make_hostile_obj.py face N OUT    one convex face of N vertices (10^5 once
                                    took 23 s in tinyobjloader's ear clipping)
  make_hostile_obj.py big MIB OUT   a valid triangle padded with comments to
                                    MIB mebibytes, for the OBJ size cap
  make_hostile_obj.py fan N OUT     N triangles 3e38 across around one shared
                                    vertex (80 000 once took 11.6 s in the
                                    split tangents' slot search: their float
                                    weights were NaN, so no face joined a slot)
  make_hostile_obj.py repeat N OUT  one triangle filling the view, N times
                                    (100 000 once took 119 s of depth tests)
  make_hostile_obj.py rle_texture   huge_rle.obj/.mtl/.tga in the current folder:
                                    a triangle whose texture is a valid 16384^2
                                    RLE TGA of 10 MiB that decodes to 1 GiB
"""
import math
import random
import sys


def soup(out):
    rng = random.Random(4)
    with open(out, "w") as f:
        for _ in range(3000):
            cx, cy, cz = (rng.uniform(-0.8, 0.8) for _ in range(3))
            for _ in range(3):
                f.write("v %.6f %.6f %.6f\n" % (cx + rng.uniform(-0.3, 0.3),
                                                cy + rng.uniform(-0.3, 0.3),
                                                cz + rng.uniform(-0.3, 0.3)))
        for i in range(3000):
            # Wound both ways, so that back-face culling keeps about half.
            a, b, c = 3 * i + 1, 3 * i + 2, 3 * i + 3
            f.write("f %d %d %d\n" % ((a, b, c) if i % 2 else (a, c, b)))


def fan(n, out):
    with open(out, "w") as f:
        f.write("v 0 0 0\n")
        for i in range(n + 1):
            angle = 2 * math.pi * i / n
            f.write("v %.7g %.7g 0\n" % (3e38 * math.cos(angle), 3e38 * math.sin(angle)))
        f.write("vt 0 0\nvt 1 0\nvt 0 1\n")
        for i in range(n):
            f.write("f 1/1 %d/2 %d/3\n" % (i + 2, i + 3))


def repeat(n, out):
    with open(out, "w") as f:
        f.write("v -10 -10 0\nv 10 -10 0\nv 0 10 0\n")
        f.write("f 1 2 3\n" * n)


def face(n, out):
    with open(out, "w") as f:
        for i in range(n):
            angle = 2 * math.pi * i / n
            f.write("v %.7f %.7f 0\n" % (0.9 * math.cos(angle), 0.9 * math.sin(angle)))
        f.write("f " + " ".join(str(i + 1) for i in range(n)) + "\n")


def big(mib, out):
    with open(out, "w") as f:
        f.write("v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0\nf 1 2 3\n")
        line = "#" * 1023 + "\n"
        for _ in range(mib * 1024):
            f.write(line)


def rle_texture():
    width = height = 16384
    with open("huge_rle.tga", "wb") as f:
        f.write(bytes([0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0]))
        f.write(width.to_bytes(2, "little") + height.to_bytes(2, "little") + bytes([32, 0]))
        # Run packets of 128 grey pixels: (width * height / 128) of them.
        f.write(bytes([0xFF, 128, 128, 128, 255]) * (width * height // 128))
    with open("huge_rle.mtl", "w") as f:
        f.write("newmtl huge\nmap_Kd huge_rle.tga\n")
    with open("huge_rle.obj", "w") as f:
        f.write("mtllib huge_rle.mtl\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0\n"
                "vt 0 0\nvt 1 0\nvt 0.5 1\nusemtl huge\nf 1/1 2/2 3/3\n")


if __name__ == "__main__":
    kind = sys.argv[1]
    if kind == "soup":
        soup(sys.argv[2])
    elif kind == "face":
        face(int(sys.argv[2]), sys.argv[3])
    elif kind == "fan":
        fan(int(sys.argv[2]), sys.argv[3])
    elif kind == "repeat":
        repeat(int(sys.argv[2]), sys.argv[3])
    elif kind == "big":
        big(int(sys.argv[2]), sys.argv[3])
    elif kind == "rle_texture":
        rle_texture()
    else:
        sys.exit("unknown kind " + kind)
