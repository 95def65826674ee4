#!/usr/bin/env bash
# Live shader reload latency: for each chapter, RUNS times, a running chapter (headless, the size
# given) has its light (or triangle) shader edited under it by tests/chapters/live_reload.sh, and the
# chapter reports how long after the edit (the file's modification time) the first frame using
# the new shader began: the poll (at most 50 ms), the compile, the new pipelines, one frame.
#   bench/reload_latency.sh [BUILD[,BUILD...]] [RUNS] [chapter options...]
# Several build trees (comma-separated) are measured side by side: each run goes through them in
# turn, so that they share the machine's state; a line per chapter and build.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
IFS=, read -ra builds <<< "${1:-$root/build}"
runs=${2:-5}
shift $(($# < 2 ? $# : 2))
options=("$@")
[ ${#options[@]} -gt 0 ] || options=(--width 1280 --height 720)
median() { printf '%s\n' "$@" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
for case in chapter-06:chapter-06/triangle.frag chapter-10:chapter-10/lighting.frag \
            chapter-14:chapter-14/light.frag chapter-15:chapter-15/light.frag \
            chapter-15-lab:chapter-15-lab/light.frag; do
    program=${case%%:*} shader=${case#*:}
    declare -A latencies=() compiles=() pipelines=()
    for _ in $(seq "$runs"); do
        for build in "${builds[@]}"; do
            line=$("$root/tests/chapters/live_reload.sh" edit "$root/shaders" "$shader" "$build/tests/bin/image_compare" \
                   "$build/bin/$program" --headless "${options[@]}" 2> /dev/null | grep '^shaders: reloaded' | tail -1)
            compiles[$build]+=" $(sed -E 's/.*compiled in ([0-9]+) ms.*/\1/' <<< "$line")"
            latencies[$build]+=" $(sed -E 's/.*first frame with it ([0-9]+) ms.*/\1/' <<< "$line")"
            made=$(sed -nE 's/.*pipelines made in ([0-9]+) ms.*/\1/p' <<< "$line")
            pipelines[$build]+=" ${made:--}"
        done
    done
    for build in "${builds[@]}"; do
        # shellcheck disable=SC2086
        printf '%-15s %-26s compile %5s ms  pipelines %5s ms  edit to first frame %5s ms  (median of %d; all: %s)  %s\n' \
            "$program" "$shader" "$(median ${compiles[$build]})" "$(median ${pipelines[$build]})" \
            "$(median ${latencies[$build]})" "$runs" "${latencies[$build]# }" "$build"
    done
    unset latencies compiles pipelines
done
