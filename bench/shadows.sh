#!/usr/bin/env bash
# chapter-16's shadows against chapter-15 (no shadows), side by side on one machine
# (docs/performance.md, "Cascade shadows"; docs/chapter-16.md).
#
#   bench/shadows.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N] [--scene ARGS]
#                    [--book-standin]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every
# configuration once in turn (so that a slower stretch of a shared machine falls on all of them):
# chapter-15; chapter-16 with the camera still, walking 2 cm a frame and turning 0.5 degrees a
# frame, with each --shadow-redraw form (scrolled, the default; changed; always, the book's); the
# point light's marker moving (--light-motion walk) under each form; the last cascade at the
# view's far plane (--shadow-far view); and the map sizes and cascade counts. Each run: the default
# scene (or --scene's arguments, one word: e.g. "--book-scene=/path/to/clone"), --benchmark
# --warmup 10 --frames N (default 40), 1280x720 unless --size. --book-standin: the book's chapter-16
# scene (--book-scene) on a clone made of stand-ins -- the Sponza stand-in (bench/sponza_standin.cpp,
# Sponza's size: 103 primitives, 267,000 triangles) and the test clone's tree (tests/tools/gltf_cases.cpp). Prints one line per run: the GPU
# medians of the frame and of each pass, and for chapter-16 how often each cascade was drawn (and
# drawn whole), and what a frame drew of each on average: texels and draws.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
rounds=3
frames=40
device=()
scene=()
size=(--width 1280 --height 720)
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        --size) size=(--width "$2" --height "$3"); shift 2 ;;
        --frames) frames=$2; shift ;;
        --scene) scene=("$2"); shift ;;
        --book-standin) scene=(book-standin) ;;
        '' | *[!0-9]*) build=$(cd "$1" && pwd) ;;
        *) rounds=$1 ;;
    esac
    shift
done
bin=$build/bin
for tool in "$bin/chapter-15" "$bin/chapter-16"; do
    [ -x "$tool" ] || { echo "shadows.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done

if [ "${scene[*]}" = book-standin ]; then
    for tool in "$build/bench/bin/sponza_standin" "$build/tests/bin/gltf_cases"; do
        [ -x "$tool" ] || { echo "shadows.sh: no $tool in the build" >&2; exit 2; }
    done
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    "$build/tests/bin/gltf_cases" "$work/gltf" > /dev/null
    sponza=$work/gltf/book/booksamples/chapter-15/resources/models/sponza
    rm -rf "$sponza"
    "$build/bench/bin/sponza_standin" "$sponza" >&2
    scene=("--book-scene=$work/gltf/book")
fi
configs=(
    "chapter-15"
    "chapter-16"
    "chapter-16 --shadow-redraw always"
    "chapter-16 --camera-motion walk"
    "chapter-16 --camera-motion walk --shadow-redraw changed"
    "chapter-16 --camera-motion walk --shadow-redraw always"
    "chapter-16 --camera-motion turn"
    "chapter-16 --camera-motion turn --shadow-redraw changed"
    "chapter-16 --camera-motion walk --light-motion walk"
    "chapter-16 --camera-motion walk --light-motion walk --shadow-redraw scrolled-together"
    "chapter-16 --camera-motion walk --light-motion walk --shadow-redraw changed"
    "chapter-16 --camera-motion walk --shadow-far view"
    "chapter-16 --shadow-redraw always --shadow-map-size 1024"
    "chapter-16 --shadow-redraw always --shadow-map-size 4096"
    "chapter-16 --shadow-redraw always --cascades 1"
    "chapter-16 --shadow-redraw always --cascades 4"
)
[ -n "${SHADOWS_CONFIGS:-}" ] && mapfile -t configs <<< "$SHADOWS_CONFIGS"  # a subset, a line each
for ((round = 1; round <= rounds; ++round)); do
    for config in "${configs[@]}"; do
        read -r -a args <<< "$config"
        out=$("$bin/${args[0]}" "${args[@]:1}" "${scene[@]}" --headless "${device[@]}" "${size[@]}" --benchmark \
            --warmup 10 --frames "$frames")
        gpu=$(awk '$1 == "GPU" {printf "%s %s ", $2, $3}' <<< "$out")
        drawn=$(sed -n 's/^chapter-16: cascades drawn \(.*\) times in [0-9]* frames (whole \(.*\))$/drawn \1 whole \2/p' <<< "$out")
        work=$(sed -n 's/^chapter-16: a frame drew \(.*\) texels and \(.*\) draws per cascade.*/| texels \1 draws \2/p' <<< "$out")
        printf '%-72s | %s%s %s\n' "$config" "$gpu" "$drawn" "$work"
    done
done
