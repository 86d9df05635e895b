#!/usr/bin/env python3
"""Writes a scene of COUNT spheres of 1,024 triangles each (tessellation 32: 32 slices, 16
stacks) on a grid four rows high, each with its own material, for bench/fps.sh (16 and 32:
what each object costs).

With --merged MESH.obj, the same spheres go into one OBJ file instead (the vertices and
triangles of lightbench's own sphere, at the same places), and the scene holds that one object,
scaled back to the size the grid has (the import helper fits a mesh in the cube [-1, 1]): the
same triangles on the same pixels, in one draw.
Usage: bench/grid_objects.py OUT.json [COUNT] [--merged MESH.obj]   (COUNT: default 16, at most
32, the scene's limit)"""
import json
import math
import sys

args = sys.argv[1:]
merged = None
if "--merged" in args:
    at = args.index("--merged")
    merged = args[at + 1]
    del args[at:at + 2]
out = args[0]
count = int(args[1]) if len(args) > 1 else 16
columns = (count + 3) // 4
rows = (count + columns - 1) // columns
SPACING, SLICES, STACKS = 2.5, 32, 16


def centre(i):
    row, col = divmod(i, columns)
    return [SPACING * (col - (columns - 1) / 2.0), SPACING * ((rows - 1) / 2.0 - row), 0.0]


def material(i):
    hue = i / float(count)
    kd = [0.3 + 0.6 * hue, 0.4, 0.9 - 0.6 * hue]
    return {"ka": kd, "kd": kd, "ks": [1, 1, 1], "shininess": 20}


def write_spheres(path):
    """makeSphere(32, 16) of render/model/mesh/mesh.cpp, once per grid place."""
    with open(path, "w") as obj:
        base = 1
        for i in range(count):
            c = centre(i)
            for r in range(STACKS + 1):
                theta = math.pi * r / STACKS
                ring = 0.0 if r in (0, STACKS) else math.sin(theta)
                for s in range(SLICES + 1):
                    phi = 2 * math.pi * (s % SLICES) / SLICES
                    n = (ring * math.sin(phi), math.cos(theta), ring * math.cos(phi))
                    obj.write("v %.6f %.6f %.6f\nvn %.6f %.6f %.6f\n" %
                              (c[0] + n[0], c[1] + n[1], c[2] + n[2], *n))
            for r in range(STACKS):
                for s in range(SLICES):
                    a = base + r * (SLICES + 1) + s
                    b = a + SLICES + 1
                    for t in ((a, b, a + 1), (a + 1, b, b + 1)):
                        obj.write("f %d//%d %d//%d %d//%d\n" % (t[0], t[0], t[1], t[1], t[2], t[2]))
            base += (STACKS + 1) * (SLICES + 1)


if merged:
    write_spheres(merged)
    # The helper centres the mesh (the grid is centred already) and scales its largest extent
    # to 2: this scale gives it back its size.
    width = SPACING * (columns - 1) + 2.0
    objects = [{"mesh": merged, "scale": [width / 2.0] * 3, "material": material(0)}]
else:
    objects = [{"shape": "sphere", "tessellation": 32, "translation": centre(i),
                "material": material(i)} for i in range(count)]
scene = {
    "format": "lightbench-scene",
    "version": 3,
    "objects": objects,
    # The grid fills about the same part of the frame whatever its width.
    "camera": {"target": [0, 0, 0], "distance": 13 * max(1.0, columns / 4.0), "yaw": 0,
               "pitch": 0},
}
with open(out, "w") as f:
    json.dump(scene, f, indent=1)
