#!/usr/bin/env python3
"""Writes a binary little-endian PLY torus with about N triangles (default 1,000,000):
float x, y, z (and nx, ny, nz with --normals) per vertex, uchar-count int faces, wound
counter-clockwise seen from outside (--clockwise: the other way, as the Stanford bunny's are).
Usage: make_ply.py OUT.ply [TRIANGLES] [--normals] [--clockwise]"""
import math
import os
import struct
import sys


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    normals = "--normals" in sys.argv
    clockwise = "--clockwise" in sys.argv
    out = args[0]
    triangles = int(args[1]) if len(args) > 1 else 1_000_000
    # rings x tubes quads, two triangles each, rings = 2 * tubes
    tubes = max(3, int(math.sqrt(triangles / 4)))
    rings = 2 * tubes
    major, minor = 0.7, 0.3
    vertex_count = rings * tubes
    face_count = 2 * rings * tubes
    props = "property float x\nproperty float y\nproperty float z\n"
    if normals:
        props += "property float nx\nproperty float ny\nproperty float nz\n"
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {vertex_count}\n{props}"
        f"element face {face_count}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    vfmt = struct.Struct("<6f" if normals else "<3f")
    # Written beside the target and renamed when complete: bench/mesh.sh generates a file only
    # when it is missing, so a run killed mid-write must not leave half a file under its name.
    part = out + ".part"
    with open(part, "wb") as f:
        f.write(header.encode("ascii"))
        buf = bytearray()
        for r in range(rings):
            u = 2 * math.pi * r / rings
            cu, su = math.cos(u), math.sin(u)
            for t in range(tubes):
                v = 2 * math.pi * t / tubes
                cv, sv = math.cos(v), math.sin(v)
                x, y, z = (major + minor * cv) * cu, minor * sv, (major + minor * cv) * su
                if normals:
                    buf += vfmt.pack(x, y, z, cv * cu, sv, cv * su)
                else:
                    buf += vfmt.pack(x, y, z)
            if len(buf) > 1 << 22:
                f.write(buf)
                buf = bytearray()
        f.write(buf)
        buf = bytearray()
        face = struct.Struct("<B3i")
        for r in range(rings):
            r1 = (r + 1) % rings
            for t in range(tubes):
                t1 = (t + 1) % tubes
                a, b, c, d = r * tubes + t, r1 * tubes + t, r1 * tubes + t1, r * tubes + t1
                if clockwise:
                    buf += face.pack(3, a, b, c)
                    buf += face.pack(3, a, c, d)
                else:
                    buf += face.pack(3, a, c, b)
                    buf += face.pack(3, a, d, c)
            if len(buf) > 1 << 22:
                f.write(buf)
                buf = bytearray()
        f.write(buf)
    os.replace(part, out)
    print(f"{out}: {vertex_count} vertices, {face_count} triangles")


if __name__ == "__main__":
    main()
