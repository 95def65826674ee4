#!/usr/bin/env bash
# What chapter-16's shadow read costs a pixel, step by step (docs/performance.md, "The shadow read,
# pixel by pixel"): chapter-16 run with its light shader replaced by each step of
# shaders/chapter-15-lab/shadow_cost.frag -- none (chapter-15's light pass), + the cascade choice,
# + the place in the map, + the texel read, + Chebyshev's bound (chapter-16's own shader, whose
# image it checks against the last step's first) -- and chapter-15 itself, side by side.
#
#   bench/shadow_read.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N]
#
# BUILD_DIR defaults to build (Release, with chapter-15-lab built: it compiles the steps; a name of
# digits alone is read as ROUNDS: write ./123); ROUNDS (default 3) rounds, each running every
# configuration once in turn. Each run: the default scene,
# the camera still, --benchmark --warmup 10 --frames N (default 40), 1280x720 unless --size.
# Prints one line a run (the GPU light pass's median and least time over the frames), then per
# configuration the medians over the rounds, the light pass's cost a pixel above the step none and
# what the step adds to the one before it (ns a pixel). Ctrl+C stops it (exit 130); a run that
# reports no light pass stops it (exit 1).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
rounds=3
frames=40
device=()
width=1280
height=720
usage() { echo "shadow_read.sh: $1 (usage: bench/shadow_read.sh [BUILD_DIR] [ROUNDS] [--device NAME] [--size W H] [--frames N])" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case $1 in
        --device) [ $# -ge 2 ] || usage "--device needs a name"; device=(--device "$2"); shift ;;
        --size) [ $# -ge 3 ] || usage "--size needs a width and a height"; width=$2; height=$3; shift 2 ;;
        --frames) [ $# -ge 2 ] || usage "--frames needs a count"; frames=$2; shift ;;
        -*) usage "unknown option $1" ;;
        *[!0-9]*) [ -d "$1" ] || usage "no build directory $1"; build=$(cd "$1" && pwd) ;;
        '') usage "an empty argument" ;;
        *) rounds=$((10#$1)); [ "$rounds" -ge 1 ] || usage "ROUNDS must be 1 or more" ;;
    esac
    shift
done
bin=$build/bin
steps=(none choice place read bound)
for file in "$bin/chapter-15" "$bin/chapter-16" "${steps[@]/#/$bin/shaders/chapter-15-lab/shadow_cost-}"; do
    file=${file%-}
    case $file in */shadow_cost-*) file=$file.frag.spv ;; esac
    [ -e "$file" ] || { echo "shadow_read.sh: build $build first (cmake --build $build): no $file" >&2; exit 2; }
done

# A copy of chapter-16 beside its shaders (the chapters find their shaders next to the program):
# the light shader is swapped there, never in the build.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap 'echo "shadow_read.sh: interrupted" >&2; exit 130' INT TERM
mkdir -p "$work/shaders"
cp "$bin/chapter-16" "$work/"
cp -rL "$bin/shaders/chapter-16" "$work/shaders/"  # -L: a copy, never a link into the build
for dir in "$bin"/shaders/*; do [ -e "$work/shaders/${dir##*/}" ] || ln -s "$dir" "$work/shaders/"; done
ln -s "$bin/scenes" "$work/scenes"
light=$work/shaders/chapter-16/light.frag.spv
cp "$light" "$work/chapter-16-light.frag.spv"
use() {
    rm -f "$light"
    if [ "$1" = chapter-16 ]; then cp "$work/chapter-16-light.frag.spv" "$light"
    else cp "$bin/shaders/chapter-15-lab/shadow_cost-$1.frag.spv" "$light"; fi
}

# The last step must be chapter-16's image, to the bit -- at 640x360 whatever --size says: at a few
# pixels the steps cannot be told apart.
for form in chapter-16 bound; do
    use "$form"
    "$work/chapter-16" --headless "${device[@]}" --width 640 --height 360 --frames 2 --screenshot "$work/$form.png" \
        > /dev/null
done
size=(--width "$width" --height "$height")
cmp -s "$work/chapter-16.png" "$work/bound.png" ||
    { echo "shadow_read.sh: the step bound does not draw chapter-16's image" >&2; exit 1; }

configs=(chapter-15 "${steps[@]}" chapter-16)
for ((round = 1; round <= rounds; ++round)); do
    for config in "${configs[@]}"; do
        if [ "$config" = chapter-15 ]; then program=$bin/chapter-15; else program=$work/chapter-16; use "$config"; fi
        out=$("$program" --headless "${device[@]}" "${size[@]}" --benchmark --warmup 10 --frames "$frames")
        line=$(awk -v c="$config" '$1 == "GPU" && $2 == "light" {print c, $3, $5}' <<< "$out")
        [ -n "$line" ] || { echo "shadow_read.sh: $config reported no GPU light pass" >&2; exit 1; }
        echo "$line" >> "$work/runs"
        awk '{printf "%-12s light pass median %8.3f ms, least %8.3f ms\n", $1, $2, $3}' <<< "$line"
    done
done

echo
echo "medians over $rounds rounds, ${width}x$height ($((width * height)) pixels); ns a pixel: above none, and what the step adds"
awk -v pixels=$((width * height)) '
    { median[$1] = median[$1] " " $2; least[$1] = least[$1] " " $3; if (!($1 in seen)) { seen[$1] = 1; order[n++] = $1 } }
    function mid(list,    a, k, i, j, t) {
        k = split(substr(list, 2), a, " ")
        for (i = 1; i <= k; ++i) for (j = i + 1; j <= k; ++j) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }
        return k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2
    }
    END {
        base = mid(median["none"]); baseLeast = mid(least["none"])
        for (i = 0; i < n; ++i) {
            m = mid(median[order[i]]); l = mid(least[order[i]])
            printf "%-12s light pass %8.3f ms (least %8.3f)   above none %+8.3f ns (least %+8.3f)", order[i], m, l,
                   (m - base) * 1e6 / pixels, (l - baseLeast) * 1e6 / pixels
            if (i > 1)  # after chapter-15 and none: what this step adds to the one before
                printf "   the step adds %+8.3f ns (least %+8.3f)", (m - previous) * 1e6 / pixels, (l - previousLeast) * 1e6 / pixels
            printf "\n"
            previous = m; previousLeast = l
        }
    }' "$work/runs"
