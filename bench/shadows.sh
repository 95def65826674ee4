#!/usr/bin/env bash
# chapter-16's shadows against chapter-15 (no shadows), side by side on one machine
# (docs/chapter-16.md, "What the shadows cost").
#
#   bench/shadows.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every
# configuration once in turn (so that a slower stretch of a shared machine falls on all of them):
# chapter-15; chapter-16 with the camera still and walking 2 cm a frame (--camera-motion walk),
# each with cascades drawn only when they changed and drawn every frame (--shadow-redraw always);
# the last cascade at the view's far plane (--shadow-far view); and the map sizes and cascade
# counts. Each run: the default scene, --benchmark --warmup 10 --frames N (default 40), 1280x720
# unless --size. Prints one line per run: the GPU medians of the frame and of each pass, and for
# chapter-16 how often each cascade was drawn.
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
for tool in "$bin/chapter-15" "$bin/chapter-16"; do
    [ -x "$tool" ] || { echo "shadows.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done

configs=(
    "chapter-15"
    "chapter-16"
    "chapter-16 --shadow-redraw always"
    "chapter-16 --camera-motion walk"
    "chapter-16 --camera-motion walk --shadow-redraw always"
    "chapter-16 --camera-motion walk --shadow-far view"
    "chapter-16 --shadow-redraw always --shadow-map-size 1024"
    "chapter-16 --shadow-redraw always --shadow-map-size 4096"
    "chapter-16 --shadow-redraw always --cascades 1"
    "chapter-16 --shadow-redraw always --cascades 4"
)
for ((round = 1; round <= rounds; ++round)); do
    for config in "${configs[@]}"; do
        read -r -a args <<< "$config"
        out=$("$bin/${args[0]}" "${args[@]:1}" --headless "${device[@]}" "${size[@]}" --benchmark --warmup 10 \
            --frames "$frames")
        gpu=$(awk '$1 == "GPU" {printf "%s %s ", $2, $3}' <<< "$out")
        drawn=$(sed -n 's/^chapter-16: cascades drawn \(.*\) times in .*/drawn \1/p' <<< "$out")
        printf '%-58s | %s%s\n' "$config" "$gpu" "$drawn"
    done
done
