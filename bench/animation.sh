#!/usr/bin/env bash
# chapter-17's animations against chapter-16, side by side on one machine (docs/chapter-17.md,
# "What the animation costs"; docs/performance.md).
#
#   bench/animation.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every
# configuration once in turn. On chapter-17's scene (the default courtyard with the walker and the
# arm, scenes/default/animated.json): chapter-16 (which draws the figures in their rest pose),
# chapter-17 with the figures playing, and paused (--animation-time); on the courtyard alone
# (scene.json: nothing animated) chapter-16 and chapter-17; and chapter-17 skinning a strip of
# 2^20 + 1 vertices (scenes/generate_figure.cpp), for the pass's time per vertex. Each run:
# --benchmark --warmup 10 --frames N (default 40), 1280x720 unless --size. Prints one line per run:
# the GPU medians of the frame and of each pass.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
rounds=3
frames=40
device=()
size=(--width 1280 --height 720)
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        --size) size=(--width "$2" --height "$3"); shift 2 ;;
        --frames) frames=$2; shift ;;
        '' | *[!0-9]*) build=$(cd "$1" && pwd) ;;
        *) rounds=$1 ;;
    esac
    shift
done
bin=$build/bin
for tool in "$bin/chapter-16" "$bin/chapter-17" "$build/tools/generate_figure"; do
    [ -x "$tool" ] || { echo "animation.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/tools/generate_figure" strip "$work/strip.gltf" 1048577
scenes=$bin/scenes/default
configs=(
    "chapter-16 --scene=$scenes/animated.json"
    "chapter-17"
    "chapter-17 --animation-time=0.4"
    "chapter-16 --scene=$scenes/scene.json"
    "chapter-17 --scene=$scenes/scene.json"
    "chapter-17 --model=$work/strip.gltf"
)
for ((round = 1; round <= rounds; ++round)); do
    for config in "${configs[@]}"; do
        read -r -a args <<< "$config"
        out=$("$bin/${args[0]}" "${args[@]:1}" --headless "${device[@]}" "${size[@]}" --benchmark \
            --warmup 10 --frames "$frames")
        gpu=$(awk '$1 == "GPU" {printf "%s %s ", $2, $3}' <<< "$out")
        printf '%-40s | %s\n' "${config//$work\//}" "$gpu"
    done
done
