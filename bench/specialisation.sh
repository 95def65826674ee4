#!/usr/bin/env bash
# Generic against specialised pipelines (--pipelines generic / specialised), side by side on one
# machine (docs/performance.md, "Pipelines made for the scene").
#
#   bench/specialisation.sh [BUILD_DIR] [RUNS] [--device NAME] [--size W H]
#
# BUILD_DIR defaults to build (Release); RUNS (default 5) alternating runs of each form, after one
# run of each that fills the pipeline cache. Scenes: the default courtyard, the Sponza stand-in
# (bench/sponza_standin.cpp, --book-scene) and the glTF scene of all the material features
# (tests/tools/gltf_cases.cpp, features/). Prints one markdown row per chapter, scene and form: the
# medians over the runs of the GPU frame, scene pass and light pass (--benchmark --warmup 10
# --frames 40, 1280x720 unless --size), the pipelines made for the scene, the time the passes took
# to make at start-up and the startup (process start to the first frame presented: lavapipe
# compiles a pipeline's shaders when it first draws with it), each with an empty pipeline cache
# (cold) and with the cache that run left (warm).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
runs=5
device=()
size=(--width 1280 --height 720)
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        --size) size=(--width "$2" --height "$3"); shift 2 ;;
        '' | *[!0-9]*) build=$(cd "$1" && pwd) ;;
        *) runs=$1 ;;
    esac
    shift
done
bin=$build/bin
for tool in "$bin/chapter-15" "$build/bench/bin/sponza_standin" "$build/tests/bin/gltf_cases"; do
    [ -x "$tool" ] || { echo "specialisation.sh: build $build first (cmake --build $build): no $tool" >&2; exit 2; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME=$work/cache
"$build/bench/bin/sponza_standin" "$work/sponza" >&2
"$build/tests/bin/gltf_cases" "$work/gltf"

# median VALUES...
median() { printf '%s\n' "$@" | sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# field OUTPUT NAME: the median column of a --benchmark row ("GPU scene"), or a report line's value.
row() { awk -v name="$2" '$0 ~ "^" name " " {print $3; exit}' <<< "$1"; }
info() { awk -v name="$2" '$1 == name {print $2; exit}' <<< "$1"; }

# compare CHAPTER SCENE_NAME ARGS...: the rows of both forms for one chapter and scene.
compare() {
    local chapter=$1 scene=$2
    shift 2
    local args=(--headless "${device[@]}" "${size[@]}" "$@")
    declare -A frame scenePass lightPass pipelines cold warm coldStart warmStart
    local form out
    for form in generic specialised; do
        rm -rf "$XDG_CACHE_HOME"
        out=$("$bin/$chapter" "${args[@]}" --pipelines "$form" --benchmark --warmup 0 --frames 1)
        cold[$form]=$(info "$out" passes_startup) coldStart[$form]=$(info "$out" startup)
        out=$("$bin/$chapter" "${args[@]}" --pipelines "$form" --benchmark --warmup 0 --frames 1)
        warm[$form]=$(info "$out" passes_startup) warmStart[$form]=$(info "$out" startup)
        pipelines[$form]=$(info "$out" scene_pipelines)
        frame[$form]="" scenePass[$form]="" lightPass[$form]=""
    done
    local i
    for ((i = 0; i < runs; ++i))
    do
        for form in generic specialised; do
            echo "bench: $chapter $scene --pipelines $form ($((i + 1))/$runs)" >&2
            out=$("$bin/$chapter" "${args[@]}" --pipelines "$form" --benchmark --warmup 10 --frames 40)
            frame[$form]+=" $(row "$out" "GPU frame")"
            scenePass[$form]+=" $(row "$out" "GPU (scene|geometry)")"
            lightPass[$form]+=" $(row "$out" "GPU (light|lighting)")"
        done
    done
    for form in generic specialised; do
        # shellcheck disable=SC2086
        echo "| $chapter | $scene | $form | $(median ${frame[$form]}) | $(median ${scenePass[$form]}) |" \
             "$(median ${lightPass[$form]}) | ${pipelines[$form]} | ${cold[$form]} / ${warm[$form]} |" \
             "${coldStart[$form]} / ${warmStart[$form]} |"
    done
}

echo "| chapter | scene | pipelines | GPU frame ms | scene pass ms | light pass ms | scene pipelines | passes made ms, cold / warm cache | startup ms, cold / warm |"
echo "|---|---|---|---|---|---|---|---|---|"
compare chapter-15 default
compare chapter-15 "Sponza stand-in" --book-scene "$work/sponza/Sponza.gltf"
compare chapter-15 "all features" --scene "$work/gltf/features/features.json"
compare chapter-14 default
compare chapter-10 default
