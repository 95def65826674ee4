#!/usr/bin/env python3
"""Load time against file size for the glTF loader (docs/reliability.md, "What a model may cost").

    bench/gltf_scaling.py BIN_DIR [BIN_DIR...]

Writes, in a temporary directory, (a) one mesh shared by N nodes (N = 1, 10, 100, 1,000, 10,000),
its POSITION 2^20 sparse zeros (no buffer view) drawn by 3 indices, and (b) a plain grid with
normals under one node (8,192, 65,522 and 524,288 triangles), each a self-contained .gltf
(data: URIs); then runs BIN_DIR/chapter-15 --headless --width 64 --height 36 --model FILE on
each, alternating the given builds, under /usr/bin/time, and prints a table of seconds and peak
resident MB per build.
"""
import base64, json, os, struct, subprocess, sys, tempfile


def write(path, root, buf):
    root["buffers"] = [{"byteLength": len(buf),
                        "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}]
    with open(path, "w") as f:
        json.dump(root, f)


def shared(path, n):
    buf = struct.pack("<I", 1) + struct.pack("<3f", 1, 0, 0) + struct.pack("<3I", 0, 1, 2)
    root = {"asset": {"version": "2.0"},
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 4},
                            {"buffer": 0, "byteOffset": 4, "byteLength": 12},
                            {"buffer": 0, "byteOffset": 16, "byteLength": 12}],
            "accessors": [{"componentType": 5126, "count": 1 << 20, "type": "VEC3",
                           "sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5125},
                                      "values": {"bufferView": 1}}},
                          {"bufferView": 2, "componentType": 5125, "count": 3, "type": "SCALAR"}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "nodes": [{"mesh": 0, "translation": [0, 0, k]} for k in range(n)],
            "scenes": [{"nodes": list(range(n))}]}
    write(path, root, buf)


def grid(path, side):
    pos = bytearray(); nor = bytearray(); idx = bytearray()
    for y in range(side + 1):
        for x in range(side + 1):
            pos += struct.pack("<3f", x, y, 0)
            nor += struct.pack("<3f", 0, 0, 1)
    for y in range(side):
        for x in range(side):
            k = y * (side + 1) + x
            idx += struct.pack("<6I", k, k + 1, k + side + 2, k, k + side + 2, k + side + 1)
    v = (side + 1) ** 2
    root = {"asset": {"version": "2.0"},
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(nor)},
                            {"buffer": 0, "byteOffset": len(pos) + len(nor), "byteLength": len(idx)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": v, "type": "VEC3",
                           "min": [0, 0, 0], "max": [side, side, 0]},
                          {"bufferView": 1, "componentType": 5126, "count": v, "type": "VEC3"},
                          {"bufferView": 2, "componentType": 5125, "count": side * side * 6, "type": "SCALAR"}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
            "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}
    write(path, root, bytes(pos + nor + idx))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    bins = sys.argv[1:]
    work = tempfile.mkdtemp()
    files = []
    for n in (1, 10, 100, 1000, 10000):
        files.append((f"{n} nodes", os.path.join(work, f"shared_{n}.gltf")))
        shared(files[-1][1], n)
    for side in (64, 181, 512):
        files.append((f"grid {2 * side * side}", os.path.join(work, f"grid_{side}.gltf")))
        grid(files[-1][1], side)
    print("| file | bytes | " + " | ".join(f"{b}: s, peak MB" for b in bins) + " |")
    print("|---|---|" + "---|" * len(bins))
    for name, path in files:
        cells = []
        for b in bins:
            timing = os.path.join(work, "time.txt")
            subprocess.run(["/usr/bin/time", "-o", timing, "-f", "%e %M", os.path.join(b, "chapter-15"),
                            "--headless", "--width", "64", "--height", "36", "--model", path],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=600)
            seconds, kb = open(timing).read().split()[-2:]
            cells.append(f"{seconds}, {int(kb) // 1024}")
        print(f"| {name} | {os.path.getsize(path):,} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
