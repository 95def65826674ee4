#!/usr/bin/env bash
# chapter-18's vertex pulling against chapter-17's vertex input, side by side on one machine
# (docs/chapter-18.md, "What pulling costs"; docs/performance.md).
#
#   bench/vertex_pulling.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every
# configuration once in turn. The same picture each way: chapter-17's scene (the courtyard with the
# walker and the arm) at a fixed animation time, every cascade redrawn every frame
# (--shadow-redraw always: the shadow pass draws the whole scene three times, as the book's does);
# and a strip of 2^20 + 1 skinned vertices (scenes/generate_figure.cpp), where vertex work is most
# of the frame. Each run: --benchmark --warmup 10 --frames N (default 40), 1280x720 unless --size.
# Prints one line per run: the GPU medians of the frame and of each pass.
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
for tool in "$bin/chapter-17" "$bin/chapter-18" "$build/tools/generate_figure"; do
    [ -x "$tool" ] || { echo "vertex_pulling.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/tools/generate_figure" strip "$work/strip.gltf" 1048577
configs=()
for chapter in chapter-17 chapter-18; do
    configs+=("$chapter --animation-time=0.4 --shadow-redraw=always")
done
for chapter in chapter-17 chapter-18; do
    configs+=("$chapter --model=$work/strip.gltf --animation-time=0.4 --shadow-redraw=always")
done
for ((round = 1; round <= rounds; ++round)); do
    for config in "${configs[@]}"; do
        read -r -a args <<< "$config"
        out=$("$bin/${args[0]}" "${args[@]:1}" --headless "${device[@]}" "${size[@]}" --benchmark \
            --warmup 10 --frames "$frames")
        gpu=$(awk '$1 == "GPU" {printf "%s %s ", $2, $3}' <<< "$out")
        printf '%-70s | %s\n' "${config//$work\//}" "$gpu"
    done
done
