#!/usr/bin/env python3
"""Writes a scene of 16 spheres of 1,024 triangles each (tessellation 32) on a 4x4 grid, each
with its own material, for bench/fps.sh. Usage: bench/sixteen_objects.py OUT.json"""
import json
import sys

objects = []
for i in range(16):
    row, col = divmod(i, 4)
    hue = i / 16.0
    kd = [0.3 + 0.6 * hue, 0.4, 0.9 - 0.6 * hue]
    objects.append({
        "shape": "sphere",
        "tessellation": 32,
        "translation": [2.5 * (col - 1.5), 2.5 * (1.5 - row), 0],
        "material": {"ka": kd, "kd": kd, "ks": [1, 1, 1], "shininess": 20},
    })
scene = {
    "format": "lightbench-scene",
    "version": 3,
    "objects": objects,
    "camera": {"target": [0, 0, 0], "distance": 13, "yaw": 0, "pitch": 0},
}
with open(sys.argv[1], "w") as out:
    json.dump(scene, out, indent=1)
