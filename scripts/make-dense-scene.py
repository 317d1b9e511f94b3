#!/usr/bin/env python3
"""Writes scenes/dense-gallery.json: the built-in gallery ("base": "gallery") plus 300 small
objects (boxes and spheres, 0.1-0.3 m across) placed 0.5-3 m from the gallery walk's path at
0.2-2.8 m height, seeded so the file is reproducible (issue 14's dense scene)."""
import json
import math
import random

WALK = [(0, 1.5), (8, 1.5), (16, 1.5), (16, -8), (8, -8), (0, -8), (0, 1.5)]  # host/scene/Gallery.cpp gallery_walk, x z
rng = random.Random(14)
segs = list(zip(WALK, WALK[1:]))
lengths = [math.dist(a, b) for a, b in segs]
objects = []
for i in range(300):
    at = rng.uniform(0, sum(lengths))
    k = 0
    while at > lengths[k]:
        at -= lengths[k]
        k += 1
    (ax, az), (bx, bz) = segs[k]
    ux, uz = (bx - ax) / lengths[k], (bz - az) / lengths[k]
    side = rng.choice((-1, 1)) * rng.uniform(0.5, 3.0)
    x, z = ax + ux * at - uz * side, az + uz * at + ux * side
    y = rng.uniform(0.2, 2.8)
    size = rng.uniform(0.1, 0.3)
    color = [round(rng.uniform(0.2, 0.95), 3) for _ in range(3)]
    o = {"name": f"small {i}", "position": [round(x, 4), round(y, 4), round(z, 4)], "color": color}
    if i % 2:
        o["box"] = [round(size, 4)] * 3
    else:
        o["sphere"] = round(size / 2, 4)
        o["segments"] = 12
    objects.append(o)
with open("scenes/dense-gallery.json", "w") as f:  # one object a line
    f.write('{\n  "name": "dense gallery",\n  "base": "gallery",\n  "objects": [\n')
    f.write(",\n".join("    " + json.dumps(o) for o in objects))
    f.write("\n  ]\n}\n")
