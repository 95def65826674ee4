#!/usr/bin/env python3
"""scenes.lights-ranges: every light of the generated lights-N scenes (bin/scenes/lights-N/scene.json,
written by scenes/generate_light_scene.cpp) is a point light with a range, and the ranges keep the
number of lights that reach a point of the floor about the same for every N (the docs say about 6).

  light_scenes.py SCENES_DIR    (the build's bin/scenes)
"""
import json
import math
import pathlib
import sys

scenes = sorted(pathlib.Path(sys.argv[1]).glob("lights-*/scene.json"), key=lambda p: int(p.parent.name[7:]))
if not scenes:
    sys.exit(f"no lights-N scenes under {sys.argv[1]}")
problems = 0
for path in scenes:
    lights = json.loads(path.read_text())["lights"]
    n = int(path.parent.name[7:])
    points = [l for l in lights if l.get("type") == "point"]
    bad = [l for l in points if not (isinstance(l.get("range"), (int, float)) and l["range"] > 0)]
    if len(points) != n or bad:
        print(f"{path}: {len(points)} point lights of {n}, {len(bad)} without a positive range")
        problems += 1
        continue
    # Sample the floor (y = 0) over the lights' extent on a 32 x 32 grid: how many ranges reach it.
    xs = [l["position"][0] for l in points]
    zs = [l["position"][2] for l in points]
    x0, x1, z0, z1 = min(xs), max(xs), min(zs), max(zs)  # once, not per sample (65,536 lights)
    bucketed = n > 1024
    grid = {}
    if bucketed:  # bucket the lights, so 65,536 lights x 1,024 samples stays quick
        size = max(l["range"] for l in points)
        for l in points:
            grid.setdefault((math.floor(l["position"][0] / size), math.floor(l["position"][2] / size)), []).append(l)
    counts = []
    for i in range(32):
        for j in range(32):
            x = x0 + (x1 - x0) * (i + 0.5) / 32
            z = z0 + (z1 - z0) * (j + 0.5) / 32
            if bucketed:
                near = [l for dx in (-1, 0, 1) for dz in (-1, 0, 1)
                        for l in grid.get((math.floor(x / size) + dx, math.floor(z / size) + dz), [])]
            else:
                near = points
            counts.append(sum(1 for l in near
                              if math.dist((x, 0.0, z), l["position"]) <= l["range"]))
    mean = sum(counts) / len(counts)
    print(f"lights-{n}: {n} point lights, each with a range; {mean:.1f} reach a point of the floor on average")
    if not 3 <= mean <= 12:
        print(f"{path}: {mean:.1f} lights reach a point of the floor on average, not about 6")
        problems += 1
sys.exit(1 if problems else 0)
