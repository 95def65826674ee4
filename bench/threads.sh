#!/usr/bin/env bash
# What the second thread buys: chapter-19 (one thread) and chapter-20 (the update on the main thread,
# recording, submission and presentation on a render thread), side by side on one machine
# (docs/chapter-20.md, "What the threads overlap"; docs/performance.md).
#
#   bench/threads.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N] [--counts "N ..."]
#
# BUILD_DIR defaults to build (Release); ROUNDS (default 3) rounds, each running every configuration
# once, the two chapters in turn: the default scene playing its animations, then scenes of N
# placements of one small mesh (bench/instance_scene.py; --counts, default "100000") with the camera
# walking (each frame a new shadow plan over every placement and every placement's matrices
# written: an expensive update). Each run: --benchmark --warmup 5 --frames N (default 30), 1280x720
# unless --size. Prints per run the CPU medians -- the frame period, the main thread's work (the
# update step; chapter-19's thread does it too), the fence wait, recording, submission with
# presentation -- and the GPU frame; then each thread's time, and the period against them:
#   chapter-19: period / (update + fence wait + record + submit), one thread doing it all;
#   chapter-20: period / max(main, render), main = update + fence wait, render = record + submit.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
rounds=3
frames=30
counts="100000"
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
for tool in "$bin/chapter-19" "$bin/chapter-20"; do
    [ -x "$tool" ] || { echo "threads.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes=("default")
for n in $counts; do
    python3 "$root/bench/instance_scene.py" "$n" "$work/instances-$n.json" "$bin/scenes/default"
    scenes+=("instances-$n")
done
for ((round = 1; round <= rounds; ++round)); do
    for scene in "${scenes[@]}"; do
        args=()
        [ "$scene" = default ] || args=(--scene "$work/$scene.json" --camera-motion walk)
        for chapter in chapter-19 chapter-20; do
            out=$("$bin/$chapter" "${args[@]}" --headless "${device[@]}" "${size[@]}" --benchmark --warmup 5 \
                --frames "$frames")
            awk -v chapter="$chapter" -v scene="$scene" '
                $1 == "CPU" && $2 == "frame" { period = $3 }
                $1 == "CPU" && $2 == "update" { update = $3 }
                $1 == "CPU" && $2 == "record" { record = $3 }
                $1 == "CPU" && $2 == "submit" { submit = $3 }
                $1 == "CPU" && $2 == "fence" { wait = $4 }
                $1 == "GPU" && $2 == "frame" { gpu = $3 }
                END {
                    main = update + wait; render = record + submit
                    if (chapter == "chapter-19") { against = main + render; how = "sum" }
                    else { against = (main > render ? main : render); how = "max" }
                    printf "%-10s %-16s | CPU frame %8.3f update %8.3f wait %8.3f record %7.3f submit %8.3f | GPU frame %8.3f | main %8.3f render %8.3f period/%s %.3f\n",
                        chapter, scene, period, update, wait, record, submit, gpu, main, render, how, period / against
                }' <<< "$out"
        done
    done
done
