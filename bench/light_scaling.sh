#!/usr/bin/env bash
# Many lights: how the frame of chapter-15-lab (chapter-15's passes) grows with the number of
# lights, for the book's loop over every light (--light-culling none) and for tiled culling, each with both forms of the light
# pass; and what a light's reach costs in accuracy (--light-cutoff against the unbounded falloff,
# with the fp64 reference renderer). The scenes are the generated bin/scenes/lights-N (N = 16 ...
# 65,536 point lights whose ranges keep the lights per point of the floor about constant).
#
#   bench/light_scaling.sh [BUILD_DIR]             this machine's Vulkan device (lavapipe here) at
#                                                  1280x720, and the cutoff curve; then the docs
#   bench/light_scaling.sh --gpu BUILD_DIR OUT_DIR on a machine with an NVIDIA GPU (headless):
#                                                  1920x1080 and 3840x2160, and one validated
#                                                  frame of every configuration; results in OUT_DIR
#   bench/light_scaling.sh --cutoff [BUILD_DIR]    the cutoff curve only (lavapipe); then the docs
#   bench/light_scaling.sh --forward [BUILD_DIR]   forward shading against deferred (lavapipe,
#                                                  1280x720, 1 ... 1,024 lights); then the docs
#   bench/light_scaling.sh --gpu-forward BUILD_DIR OUT_DIR   the same on the NVIDIA machine
#                                                  (1920x1080, 3840x2160), with validation (also
#                                                  part of --gpu)
#   bench/light_scaling.sh --report [BUILD_DIR]    the docs from bench/results/*.tsv only
#
# Results go to bench/results/light-scaling-*.tsv, forward-deferred-*.tsv and light-cutoff-lavapipe.tsv (kept in the
# repository: the docs' tables and plots are made from them), the tables into docs/performance.md
# and docs/accuracy.md between their "light-scaling" and "light-cutoff" markers, the plots into
# docs/images/light-scaling.svg and light-cutoff.svg (gnuplot: apt-get install gnuplot-nox).
# The loop is measured up to the N where one frame still takes seconds, not minutes, on lavapipe.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
results=$root/bench/results
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME=$work/cache
counts=(16 64 256 1024 4096 16384 65536)

# median ROW FILE: the median column of "GPU ROW" in a --benchmark report ("-" when absent).
median() { awk -v row="$2" '$1 == "GPU" && $2 == row {print $3; found = 1} END {if (!found) print "-"}' "$1"; }
field() { awk -v name="$2" '$1 == name {$1 = ""; print substr($0, 2); exit}' "$1"; }

# measure DEVICE W H N CULLING FORM WARMUP FRAMES: one benchmark, one TSV row on stdout.
measure() {
    local device=$1 w=$2 h=$3 n=$4 culling=$5 form=$6
    echo "light_scaling: $device ${w}x$h $n lights, culling $culling, $form" >&2
    "$bin/chapter-15-lab" --headless --device "$device" --width "$w" --height "$h" \
        --scene "$bin/scenes/lights-$n/scene.json" --light-culling "$culling" --light-pass "$form" \
        --benchmark --warmup "$7" --frames "$8" > "$work/run.txt"
    printf '%s\t%sx%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(field "$work/run.txt" device) ($(field "$work/run.txt" driver))" \
        "$w" "$h" "$n" "$culling" "$form" \
        "$(median "$work/run.txt" frame)" "$(median "$work/run.txt" cull)" "$(median "$work/run.txt" light)"
}

header=$'device\tsize\tlights\tculling\tform\tframe_ms\tcull_ms\tlight_ms'

# scaling DEVICE W H LOOP_MAX: every N tiled (both forms), the loop (both forms) up to LOOP_MAX.
scaling() {
    local device=$1 w=$2 h=$3 loopMax=$4 n form
    for n in "${counts[@]}"; do
        for form in fragment compute; do
            measure "$device" "$w" "$h" "$n" tiled "$form" 3 20
            if [ "$n" -le "$loopMax" ]; then
                if [ "$n" -ge 1024 ]; then measure "$device" "$w" "$h" "$n" none "$form" 0 2
                else measure "$device" "$w" "$h" "$n" none "$form" 2 10; fi
            fi
        done
    done
}

# cutoff: lavapipe, 1280x720, lights-1024 without ranges; for each cutoff the frame time (tiled,
# fragment) and the error of the windowed image against the fp64 reference of the unbounded one,
# both from the reference G-buffer layout (fp32 positions: the error is the window's alone). Small
# cutoffs reach as far as the loop and cost as much (seconds a frame): 1 warm-up frame (lavapipe
# compiles shaders on first use), 2 measured.
cutoff() {
    local scene=$work/lights-1024-unbounded.json e compare=()
    local cutoffs=(1 0.3 0.1 0.03 0.01 0.003 0.001 0.0003 0.0001 0.00003 0.00001)
    "$build/tools/generate_light_scene" "$bin/scenes/default" 1024 "$scene" --no-range > /dev/null
    local size=(--headless --device llvmpipe --width 1280 --height 720 --scene "$scene" --gbuffer reference)
    echo "light_scaling: cutoff, the unbounded loop" >&2
    "$bin/chapter-15-lab" "${size[@]}" --benchmark --warmup 1 --frames 1 --dump "$work/unbounded" > "$work/none.txt"
    for e in "${cutoffs[@]}"; do
        echo "light_scaling: cutoff $e" >&2
        "$bin/chapter-15-lab" "${size[@]}" --light-culling tiled --light-cutoff "$e" --benchmark --warmup 1 --frames 2 \
            --dump "$work/cut-$e" > "$work/cut-$e.txt"
        compare+=(--compare "E$e=$work/cut-$e/light.pfm")
    done
    # One fp64 reference render, every cutoff compared with it. Its line per image:
    # "NAME   max abs A/255  RMSE R/255 ...".
    "$build/tests/bin/reference_render" "$scene" "$work/unbounded" "${compare[@]}" > "$work/ref.txt" || true
    printf 'none\t%s\t%s\t-\t-\n' "$(median "$work/none.txt" frame)" "$(median "$work/none.txt" light)"
    for e in "${cutoffs[@]}"; do
        local maxabs rmse
        read -r maxabs rmse < <(awk -v n="E$e" '$1 == n {sub("/255", "", $4); sub("/255", "", $6); print $4, $6}' "$work/ref.txt")
        printf '%s\t%s\t%s\t%s\t%s\n' "$e" "$(median "$work/cut-$e.txt" frame)" "$(median "$work/cut-$e.txt" light)" \
            "$maxabs" "$rmse"
    done
}

# Where deferred shading earns its G-buffer: --shading forward (the scene pass shades every
# fragment it draws with every light) against the deferred loop and tiled culling (the book's
# G-buffer, both light-pass forms), one after the other for each N, on scenes from the same generator
# (N = 1 ... 1,024; below 16 made here). forward_row DEVICE W H N SHADING CULLING FORM WARMUP FRAMES.
forward_counts=(1 2 4 8 16 64 256 1024)
forward_row() {
    local device=$1 w=$2 h=$3 n=$4 shading=$5 culling=$6 form=$7
    local scene=$work/lights-$n.json
    [ -f "$scene" ] || "$build/tools/generate_light_scene" "$bin/scenes/default" "$n" "$scene" > /dev/null
    echo "light_scaling: $device ${w}x$h $n lights, $shading, culling $culling, $form" >&2
    "$bin/chapter-15-lab" --headless --device "$device" --width "$w" --height "$h" --scene "$scene" \
        --shading "$shading" --light-culling "$culling" --light-pass "$form" \
        --benchmark --warmup "$8" --frames "$9" > "$work/run.txt"
    printf '%s\t%sx%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(field "$work/run.txt" device) ($(field "$work/run.txt" driver))" \
        "$w" "$h" "$n" "$shading" "$culling" "$form" "$(median "$work/run.txt" frame)" \
        "$(if [ "$shading" = forward ]; then median "$work/run.txt" forward; else median "$work/run.txt" scene; fi)" \
        "$(median "$work/run.txt" cull)" "$(median "$work/run.txt" light)"
}
forward_header=$'device\tsize\tlights\tshading\tculling\tform\tframe_ms\tscene_ms\tcull_ms\tlight_ms'
forward_study() {
    local device=$1 w=$2 h=$3 n warmup frames form
    for n in "${forward_counts[@]}"; do
        if [ "$n" -ge 256 ]; then warmup=0 frames=2; else warmup=2 frames=10; fi
        forward_row "$device" "$w" "$h" "$n" forward none fragment "$warmup" "$frames"
        for form in fragment compute; do
            forward_row "$device" "$w" "$h" "$n" deferred none "$form" "$warmup" "$frames"
            forward_row "$device" "$w" "$h" "$n" deferred tiled "$form" 3 20
        done
    done
}

# gpu_forward: the forward study on the NVIDIA machine, and one validated 3-frame run of forward
# shading on three scenes (the message count).
gpu_forward() {
    local messages=0 scene
    for scene in default lights-16 lights-1024; do
        "$bin/chapter-15-lab" --headless --device NVIDIA --width 1920 --height 1080 --validation \
            --scene "$bin/scenes/$scene/scene.json" --shading forward --frames 3 > /dev/null 2> "$work/err.txt" || echo "validation run failed: $scene" >> "$work/err.txt"
        cat "$work/err.txt" >> "$out/forward-deferred-gpu-validation.log"
        messages=$((messages + $(grep -c "^validation" "$work/err.txt" || true)))
    done
    echo "$messages" > "$out/forward-deferred-gpu-validation.txt"
    { echo "$forward_header"; forward_study NVIDIA 1920 1080; forward_study NVIDIA 3840 2160; } > "$out/forward-deferred-gpu.tsv"
}

case "${1:-}" in
--gpu)
    build=$(cd "$2" && pwd) bin=$build/bin out=$3
    mkdir -p "$out"
    { echo "$header"; scaling NVIDIA 1920 1080 65536; scaling NVIDIA 3840 2160 16384; } > "$out/light-scaling-gpu.tsv"
    # One validated frame of every configuration: the message count.
    messages=0
    for n in "${counts[@]}"; do
        for culling in none tiled; do
            for form in fragment compute; do
                "$bin/chapter-15-lab" --headless --device NVIDIA --width 1920 --height 1080 --validation \
                    --scene "$bin/scenes/lights-$n/scene.json" --light-culling $culling --light-pass $form \
                    --frames 3 > /dev/null 2> "$work/err.txt" || true
                messages=$((messages + $(grep -c "^validation" "$work/err.txt" || true)))
            done
        done
    done
    echo "$messages" > "$out/light-scaling-gpu-validation.txt"
    gpu_forward
    exit 0
    ;;
--gpu-forward)
    build=$(cd "$2" && pwd) bin=$build/bin out=$3
    mkdir -p "$out"
    gpu_forward
    exit 0
    ;;
--report)
    ;;
--forward)
    build=$(cd "${2:-$root/build}" && pwd) bin=$build/bin
    { echo "$forward_header"; forward_study llvmpipe 1280 720; } > "$results/forward-deferred-lavapipe.tsv"
    ;;
--cutoff)
    build=$(cd "${2:-$root/build}" && pwd) bin=$build/bin
    { printf 'cutoff\tframe_ms\tlight_ms\tmax_abs_255\trmse_255\n'; cutoff; } > "$results/light-cutoff-lavapipe.tsv"
    ;;
*)
    build=$(cd "${1:-$root/build}" && pwd) bin=$build/bin
    { echo "$header"; scaling llvmpipe 1280 720 4096; } > "$results/light-scaling-lavapipe.tsv"
    { printf 'cutoff\tframe_ms\tlight_ms\tmax_abs_255\trmse_255\n'; cutoff; } > "$results/light-cutoff-lavapipe.tsv"
    ;;
esac
"$root/bench/light_report.sh"
