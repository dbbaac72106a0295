#!/usr/bin/env python3
"""Regenerates the glTF fixtures: fixtures/gltf/ (copies of the Assimp skins) and the bad
glTF inputs in fixtures/bad/.

    python3 tools/make_gltf_fixtures.py [shared-data-dir]

Each bad .gltf is one small valid file (a Hips/Spine skeleton with a three-key rotation
channel on Spine, buffer embedded as a data URI) broken in exactly one way; truncated.glb
is the first half of quad_skin.glb, garbage.glb is seeded random bytes. Output is
deterministic.
"""
import base64
import json
import math
import os
import random
import shutil
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data")
out = os.path.join(ROOT, "fixtures", "bad") + os.sep


def doc(times, rots, byte_length=None, view_for_output=1, interp="LINEAR", nodes=None, count_override=None):
    data = struct.pack("<%df" % len(times), *times) + struct.pack("<%df" % (4 * len(rots)), *[c for q in rots for c in q])
    n = len(times) if count_override is None else count_override
    return {
        "asset": {"version": "2.0", "generator": "mocapfill fixture (hand-made bad input)"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes or [{"name": "Hips", "children": [1]}, {"name": "Spine", "translation": [0, 0.1, 0]}],
        "animations": [{"name": "bend",
                        "channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}}],
                        "samplers": [{"input": 0, "output": 1, "interpolation": interp}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "SCALAR",
             "min": [times[0]] if n else [0], "max": [times[-1]] if n else [0]},
            {"bufferView": view_for_output, "componentType": 5126, "count": n, "type": "VEC4"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": max(4, 4 * len(times))},
                        {"buffer": 0, "byteOffset": 4 * len(times), "byteLength": max(16, 16 * len(rots))}],
        "buffers": [{"byteLength": byte_length or len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }

s = math.sqrt(0.5)
times = [0.0, 0.5, 1.0]
rots = [(0, 0, 0, 1), (s, 0, 0, s), (1, 0, 0, 0)]

def write(name, d):
    with open(out + name, "w") as f:
        json.dump(d, f, indent=1)
        f.write("\n")

write("short_buffer.gltf", doc(times, rots, byte_length=120))
write("out_of_range_accessor.gltf", doc(times, rots, view_for_output=7))
# Chest and Neck are each other's parent (each has one parent, so only the cycle is wrong).
write("cyclic_nodes.gltf", doc(times, rots, nodes=[{"name": "Hips", "children": [1]},
                                                  {"name": "Spine"},
                                                  {"name": "Chest", "children": [3]},
                                                  {"name": "Neck", "children": [2]}]))
write("nan_rotation.gltf", doc(times, [rots[0], (float("nan"), 0, 0, s), rots[2]]))
# Zero keys: the sampler's input and output accessors have count 0 (one placeholder float each in the buffer).
write("empty_animation.gltf", doc([0.0], [(0, 0, 0, 1)], count_override=0))

rng = random.Random(20240602)
with open(out + "garbage.glb", "wb") as f:
    f.write(bytes(rng.randrange(256) for _ in range(1024)))
with open(os.path.join(DATA, "assimp", "quad_skin.glb"), "rb") as f:
    glb = f.read()
with open(out + "truncated.glb", "wb") as f:
    f.write(glb[: len(glb) // 2])

for name in ("simple_skin.gltf", "quad_skin.glb"):
    shutil.copyfile(os.path.join(DATA, "assimp", name), os.path.join(ROOT, "fixtures", "gltf", name))
