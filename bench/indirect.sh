#!/usr/bin/env bash
# What a frame costs to record and to draw, with a draw call per mesh (chapter-17, chapter-18) and
# with indirect drawing (chapter-19), side by side on one machine (docs/chapter-19.md, "What
# recording costs"; docs/performance.md).
#
#   bench/indirect.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N] [--counts "N ..."]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every configuration
# once in turn: the default scene at a fixed animation time, then scenes of N placements of one small
# mesh (bench/instance_scene.py; --counts, default "100 1000 10000 100000"), each with the three
# chapters. Each run: --benchmark --warmup 5 --frames N (default 20), 1280x720 unless --size. Prints
# one line per run: the CPU medians of the update step and of recording, and the GPU medians of the
# frame and of each pass.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
rounds=3
frames=20
counts="100 1000 10000 100000"
device=()
size=(--width 1280 --height 720)
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        --size) size=(--width "$2" --height "$3"); shift 2 ;;
        --frames) frames=$2; shift ;;
        --counts) counts=$2; shift ;;
        '' | *[!0-9]*) build=$(cd "$1" && pwd) ;;
        *) rounds=$1 ;;
    esac
    shift
done
bin=$build/bin
for tool in "$bin/chapter-17" "$bin/chapter-18" "$bin/chapter-19"; do
    [ -x "$tool" ] || { echo "indirect.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes=("--animation-time=0.4")
for n in $counts; do
    python3 "$root/bench/instance_scene.py" "$n" "$work/instances-$n.json" "$bin/scenes/default"
    scenes+=("--scene=$work/instances-$n.json")
done
for ((round = 1; round <= rounds; ++round)); do
    for scene in "${scenes[@]}"; do
        for chapter in chapter-17 chapter-18 chapter-19; do
            out=$("$bin/$chapter" "$scene" --headless "${device[@]}" "${size[@]}" --benchmark --warmup 5 \
                --frames "$frames")
            cpu=$(awk '$1 == "CPU" && ($2 == "update" || $2 == "record") {printf "%s %s ", $2, $3}' <<< "$out")
            gpu=$(awk '$1 == "GPU" {printf "%s %s ", $2, $3}' <<< "$out")
            printf '%-10s %-34s | CPU %s| GPU %s\n' "$chapter" "${scene//$work\//}" "$cpu" "$gpu"
        done
    done
done
