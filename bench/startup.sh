#!/usr/bin/env bash
# Startup, peak memory and frame time on a model of the book's Sponza's size and kind
# (docs/performance.md, "The book's scene"). The repository has no Sponza: bench/sponza_standin.cpp
# writes a stand-in of the same size and kind (103 primitives, about 267,000 triangles, 25
# materials, 68 images of 1024x1024) as glTF and as OBJ + MTL over the same images.
#
#   bench/startup.sh [BUILD_DIR] [RUNS] [--device NAME]
#
# BUILD_DIR defaults to build (Release). Each form is run RUNS times (default 5) after one run that
# fills the pipeline cache (kept in a directory of this script's own): chapter-15 with
# --book-scene on the stand-in's Sponza.gltf, with a scene file of the same camera and lights on
# its sponza.obj, and on the default scene. Prints, per form, startup (process start to the first
# presented frame, --benchmark's figure) and peak resident memory (/usr/bin/time) as
# min / median / max, then the frame time of chapters 10, 14 and 15 on the glTF form at 1280x720.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
runs=5
device=()
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        '' | *[!0-9]*) build=$(cd "$1" && pwd) ;;
        *) runs=$1 ;;
    esac
    shift
done
bin=$build/bin
[ -x "$bin/chapter-15" ] && [ -x "$build/bench/bin/sponza_standin" ] ||
    { echo "startup.sh: build $build first (cmake --build $build)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "startup.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME=$work/cache
"$build/bench/bin/sponza_standin" "$work/sponza" >&2

# The OBJ form with the camera and lights that --book-scene gives the glTF form.
cat > "$work/sponza/scene-obj.json" <<EOF
{
  "models": [
    {"file": "sponza.obj"},
    {"file": "$bin/scenes/default/cube.gltf", "position": [5, 3.4, 1.2], "scale": 0.1}
  ],
  "camera": {"position": [0, 5, 0], "yaw": 90, "pitch": -20, "fov": 60, "near": 1, "far": 50},
  "ambient": {"color": [1, 1, 1], "intensity": 0.2},
  "lights": [
    {"type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1], "intensity": 1},
    {"type": "point", "position": [5, 3.4, 1.2], "color": [0, 1, 0], "intensity": 1, "marker": 1}
  ]
}
EOF

# stats VALUES...: "min / median / max" of the numbers.
stats() {
    printf '%s\n' "$@" | sort -n | awk '{v[NR] = $1} END {printf "%s / %s / %s", v[1], v[int((NR + 1) / 2)], v[NR]}'
}

size=(--width 1280 --height 720)
echo "| form | startup ms, min / median / max | peak resident MB, min / median / max | command |"
echo "|---|---|---|---|"
for form in gltf obj default; do
    case $form in
        gltf) args=(--book-scene "$work/sponza/Sponza.gltf") ;;
        obj) args=(--scene "$work/sponza/scene-obj.json") ;;
        default) args=() ;;
    esac
    "$bin/chapter-15" --headless "${device[@]}" "${size[@]}" "${args[@]}" --benchmark --warmup 0 --frames 1 > /dev/null
    startups=() peaks=()
    for _ in $(seq "$runs"); do
        out=$(/usr/bin/time -f 'peak %M' "$bin/chapter-15" --headless "${device[@]}" "${size[@]}" "${args[@]}" \
                  --benchmark --warmup 0 --frames 1 2>&1)
        startups+=("$(awk '/^startup/ {print $2}' <<<"$out")")
        peaks+=("$(awk '/^peak/ {printf "%.0f", $2 / 1024}' <<<"$out")")
    done
    shown=${args[*]:-}
    shown=${shown//$work\/sponza/DIR}
    echo "| $form | $(stats "${startups[@]}") | $(stats "${peaks[@]}") |" \
         "\`chapter-15 --headless ${size[*]} ${shown:+$shown }--benchmark --warmup 0 --frames 1\` |"
done

echo
echo "| chapter | CPU frame ms, median (p95) | GPU frame ms, median (p95) | command |"
echo "|---|---|---|---|"
for n in 10 14 15; do
    out=$("$bin/chapter-$n" --headless "${device[@]}" "${size[@]}" --book-scene "$work/sponza/Sponza.gltf" \
              --benchmark --warmup 5 --frames 20)
    cpu=$(awk '/^CPU frame/ {printf "%s (%s)", $3, $4}' <<<"$out")
    gpu=$(awk '/^GPU frame/ {printf "%s (%s)", $3, $4}' <<<"$out")
    echo "| chapter-$n | $cpu | $gpu | \`chapter-$n --headless ${size[*]} --book-scene DIR/Sponza.gltf --benchmark --warmup 5 --frames 20\` |"
done
echo
echo "(DIR: the stand-in, bench/bin/sponza_standin DIR; device: $(awk -F'  +' '/^device/ {print $2}' <<<"$out"))"
