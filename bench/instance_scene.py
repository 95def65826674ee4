#!/usr/bin/env python3
"""A scene of N instances of one small mesh, for chapter-19's instanced drawing (tests/chapters/
chapter-19.cmake, bench/indirect.sh): N copies of the default scene's cube, one model and one
material, on a square grid over a floor, under the sun, seen from above at an angle.

  instance_scene.py N OUT.json DEFAULT_SCENE_DIR      (DEFAULT_SCENE_DIR: the build's bin/scenes/default)

Every copy is the same model file without material overrides, so the chapters share its mesh and
material among all N draws: chapter-19 draws them with one command of N instances.
"""
import json
import math
import pathlib
import sys

if len(sys.argv) != 4 or not sys.argv[1].isdigit() or not 1 <= int(sys.argv[1]) <= 100000:
    sys.exit("usage: instance_scene.py N OUT.json DEFAULT_SCENE_DIR   (N from 1 to 100000)")
n = int(sys.argv[1])
out = pathlib.Path(sys.argv[2])
cube = (pathlib.Path(sys.argv[3]) / "cube.obj").resolve()
if not cube.is_file():
    sys.exit(f"instance_scene.py: no {cube}")
side = math.ceil(math.sqrt(n))
spacing = 20.0 / side  # the grid spans 20 m whatever N is
scale = spacing * 0.35
models = [{"file": str(cube), "position": [(-10.0 + spacing * (i % side + 0.5)), scale * 0.5,
                                           (-10.0 + spacing * (i // side + 0.5))],
           "rotation": [0.0, 37.0 * i % 360.0, 0.0], "scale": [scale, scale, scale]} for i in range(n)]
scene = {
    "ambient": {"color": [1.0, 1.0, 1.0], "intensity": 0.2},
    "camera": {"position": [0.0, 14.0, 16.0], "yaw": 0.0, "pitch": -40.0, "fov": 60.0, "near": 0.1, "far": 60.0},
    "lights": [{"type": "directional", "direction": [0.3, -1.0, -0.4], "color": [1.0, 1.0, 1.0], "intensity": 1.0}],
    "models": models,
}
out.write_text(json.dumps(scene))
