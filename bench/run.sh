#!/usr/bin/env bash
# Runs every chapter's --benchmark and writes the figures into docs/performance.md.
#
#   bench/run.sh [BUILD_DIR]                 this machine's Vulkan device (lavapipe here): every
#                                            chapter at 1280x720 and 1920x1080, chapter-15 per
#                                            G-buffer layout, windowed under Xvfb too when
#                                            xvfb-run is there; writes the "lavapipe" section
#   bench/run.sh --gpu BUILD_DIR OUT_DIR     on a machine with an NVIDIA GPU (headless): the same at
#                                            1920x1080 and 3840x2160 on the NVIDIA device, plus the
#                                            bandwidth probe; leaves OUT_DIR/gpu.tar of JSON reports
#   bench/run.sh --gpu-report TAR [BUILD_DIR]  writes the "gpu" section from that gpu.tar
#
# BUILD_DIR defaults to build (configured Release: cmake -S . -B build && cmake --build build).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
doc=$root/docs/performance.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Pipeline caches of these runs stay in here, not in the user's ~/.cache.
export XDG_CACHE_HOME=$work/cache

# run NAME CHAPTER ARGS...: one benchmark, its JSON report in $work/NAME.json. A one-frame run
# first fills the pipeline cache, so the startup reported is the usual one, with a warm cache
# (cold_startup measures the first run of each chapter).
run() {
    local name=$1 chapter=$2
    shift 2
    echo "bench: $chapter $*" >&2
    "$bin/$chapter" "$@" --warmup 0 --frames 1 > /dev/null
    "$bin/$chapter" "$@" --json "$work/$name.json" > "$work/$name.txt"
}

# cold_startup DEVICE: markdown rows of each chapter's startup (1280x720, headless) with an empty
# pipeline cache, then with the cache that run left.
cold_startup() {
    local n cold warm
    for n in 06 10 14 15; do
        rm -rf "$XDG_CACHE_HOME"
        cold=$("$bin/chapter-$n" --headless --device "$1" --benchmark --warmup 0 --frames 1 | awk '/^startup/ {print $2}')
        warm=$("$bin/chapter-$n" --headless --device "$1" --benchmark --warmup 0 --frames 1 | awk '/^startup/ {print $2}')
        echo "| chapter-$n | $cold | $warm |"
    done
}

# all_chapters DEVICE W H SUFFIX ARGS...: chapters 06, 10, 14 and 15 (per layout) at one
# resolution, with ARGS (--headless); SUFFIX ends the report names.
all_chapters() {
    local device=$1 w=$2 h=$3 suffix=$4
    shift 4
    local size=(--device "$device" --width "$w" --height "$h" --benchmark)
    run "06-${w}x$h$suffix" chapter-06 "$@" "${size[@]}" --warmup 20 --frames 300
    run "10-${w}x$h$suffix" chapter-10 "$@" "${size[@]}" --warmup 5 --frames 40
    run "14-${w}x$h$suffix" chapter-14 "$@" "${size[@]}" --warmup 5 --frames 40
    # The book's layout is chapter-15 itself; the others are the lab's (chapter-15-lab --gbuffer).
    run "15-${w}x$h-book$suffix" chapter-15 "$@" "${size[@]}" --warmup 5 --frames 40
    for layout in compact reference; do
        run "15-${w}x$h-$layout$suffix" chapter-15-lab "$@" "${size[@]}" --warmup 5 --frames 40 --gbuffer "$layout"
    done
    for layout in book compact; do
        run "15-${w}x$h-$layout-compute$suffix" chapter-15-lab "$@" "${size[@]}" --warmup 5 --frames 40 \
            --gbuffer "$layout" --light-pass compute
    done
}

# names SIZE SUFFIX: the report files all_chapters wrote, in table order.
names() {
    for n in 06 10 14; do echo "$work/$n-$1$2.json"; done
    for layout in book compact reference book-compute compact-compute; do echo "$work/15-$1-$layout$2.json"; done
}

# paste SECTION TEXT: replaces docs/performance.md between the section's markers.
paste_section() {
    local begin="<!-- $1:begin (written by bench/run.sh) -->" end="<!-- $1:end -->"
    grep -qF "$begin" "$doc" || { echo "run.sh: $doc has no $1 markers" >&2; exit 1; }
    printf '%s\n' "$2" > "$work/section.md"
    awk -v begin="$begin" -v end="$end" -v section="$work/section.md" '
        $0 == begin { print; while ((getline line < section) > 0) print line; skip = 1; next }
        $0 == end { skip = 0 }
        !skip { print }' "$doc" > "$work/doc.md"
    cp "$work/doc.md" "$doc"
    echo "run.sh: wrote the $1 section of $doc" >&2
}

# field NAME: a line of the bandwidth probe's output (device, driver).
field() {
    awk -v name="$1" '$1 == name {$1=""; print substr($0,2)}' "$work/bandwidth.txt"
}

# results PROBE: the measured part of a section, from what $work holds: the bandwidth probe (run
# as PROBE), the frame table of $reports, the startup table, the G-buffer traffic of $layouts.
results() {
    cat <<MARKDOWN
Bandwidth probe (\`$1\`: a vkCmdCopyBuffer between device-local buffers, timestamps, median of 10):
$(sed -n 's/^copy *\(.*\)/copy: \1/p; s/^bandwidth *\(.*\)/**\1**/p' "$work/bandwidth.txt" | paste -sd ' ')

$("$table" frames "${reports[@]}")

Startup (ms, 1280x720 headless, \`chapter-NN --headless --benchmark --warmup 0 --frames 1\`), the first
run with an empty pipeline cache, the second with the cache the first left:

| chapter | empty cache | warm cache |
|---|---|---|
$(cat "$work/startup.md")

G-buffer traffic against the measured bandwidth (a G-buffer written once by the scene pass and
read once by the light pass, depth included):

$("$table" bytes "$work/bandwidth.json" "${layouts[@]}")
MARKDOWN
}

machine() {
    echo "$(nproc) cores of $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)," \
         "$(awk '/^MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
}

case "${1:-}" in
--gpu)
    bin=$2/bin
    out=$3
    "$2/bench/bin/bandwidth" --device NVIDIA --mib 1024 --json "$work/bandwidth.json" > "$work/bandwidth.txt"
    cold_startup NVIDIA > "$work/startup.md"
    for size in "1920 1080" "3840 2160"; do
        read -r w h <<< "$size"
        all_chapters NVIDIA "$w" "$h" "" --headless
    done
    machine > "$work/machine.txt"
    tar -C "$work" -cf "$out/gpu.tar" .
    ;;
--gpu-report)
    build=$(cd "${3:-$root/build}" && pwd)
    tar -C "$work" -xf "$2"
    table=$build/bench/bin/benchmark_table
    mapfile -t reports < <(names 1920x1080 ""; names 3840x2160 "")
    mapfile -t layouts < <(for size in 1920x1080 3840x2160; do names $size "" | grep /15-; done)
    section=$(cat <<MARKDOWN
Measured on **$(field device)** ($(field driver); host: $(cat "$work/machine.txt")), $(date -u +%Y-%m-%d), by
\`bench/run.sh --gpu\` (Release binaries built on the lavapipe machine, copied to this one and run
headless; every command below also had \`--json FILE\`). <!-- no test: how the figures were measured -->

$(results "bandwidth --device NVIDIA --mib 1024")
MARKDOWN
)
    paste_section gpu "$section"
    ;;
*)
    build=$(cd "${1:-$root/build}" && pwd)
    bin=$build/bin
    table=$build/bench/bin/benchmark_table
    "$build/bench/bin/bandwidth" --device llvmpipe --mib 256 --json "$work/bandwidth.json" > "$work/bandwidth.txt"
    cold_startup llvmpipe > "$work/startup.md"
    for size in "1280 720" "1920 1080"; do
        read -r w h <<< "$size"
        all_chapters llvmpipe "$w" "$h" "" --headless
    done
    windowed=""
    if command -v xvfb-run > /dev/null; then
        # Windowed, no vsync (IMMEDIATE or MAILBOX), on an X server in memory: adds the present.
        xvfb-run -a -s "-screen 0 1920x1080x24" bash -c "set -euo pipefail; $(declare -f run all_chapters); bin=$bin work=$work XDG_CACHE_HOME=$XDG_CACHE_HOME
            all_chapters llvmpipe 1280 720 -window"
        windowed=yes
    fi
    mapfile -t reports < <(names 1280x720 ""; names 1920x1080 ""; [ -z "$windowed" ] || names 1280x720 -window)
    mapfile -t layouts < <(for size in 1280x720 1920x1080; do names $size "" | grep /15-; done)
    section=$(cat <<MARKDOWN
Measured on **$(field device)** ($(field driver); $(machine)), $(date -u +%Y-%m-%d), by \`bench/run.sh\` (every
command below also had \`--json FILE\`; the binaries are \`build/bin/chapter-NN\`, Release).

$(results "bandwidth --device llvmpipe --mib 256")
MARKDOWN
)
    paste_section lavapipe "$section"
    ;;
esac
