#!/usr/bin/env bash
# Fuzzes the loaders (docs/reliability.md): builds the libFuzzer targets of tests/reliability/fuzz/
# with clang (into build-fuzz/ unless FUZZ_BUILD_DIR says otherwise) and runs each target for
# SECONDS (default 60), one after the other, over a copy of its committed corpus
# (tests/reliability/fuzz/corpus/<obj|scene|gltf>/), which is never written to unless --merge is given.
#
#   tests/reliability/fuzz/run.sh [SECONDS] [--merge]
#   tests/reliability/fuzz/run.sh --build-only       (the build alone: the fuzz-targets target of the main build)
#
# --merge: afterwards, add the inputs that reach new edges to the committed corpus (libFuzzer
#          -merge=1 without hit counts, which keeps it small); for a developer's long run, never in CI.
# Environment: FUZZ_CXX (default clang++-14), FUZZ_BUILD_DIR (default <repo>/build-fuzz),
# FUZZ_TARGETS (default "obj scene gltf").
# Prints runs, speed, coverage and corpus per target; exits non-zero on any crash, timeout,
# leak, out-of-memory or sanitizer report (the input is kept under <build>/artifacts/).
set -euo pipefail

seconds=60
merge=0
build_only=0
for arg in "$@"; do
    case $arg in
        --merge) merge=1 ;;
        --build-only) build_only=1 ;;
        '' | *[!0-9]*)
            echo "usage: tests/reliability/fuzz/run.sh [SECONDS] [--merge] | --build-only" >&2
            exit 2
            ;;
        *) seconds=$arg ;;
    esac
done

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
cxx=${FUZZ_CXX:-clang++-14}

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
fi
cmake --build "$build" -j 2 >/dev/null || cmake --build "$build" -j 1  # again, to show the error
[ "$build_only" -eq 1 ] && exit 0

# Symbolized stack traces in sanitizer reports; every report ends the run.
symbolizer=$(command -v "llvm-symbolizer-${cxx##*-}" || command -v llvm-symbolizer || true)
[ -n "$symbolizer" ] && export ASAN_SYMBOLIZER_PATH=$symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# fuzz_obj writes each input as files into a directory of its own under $TMPDIR; one that crashes
# leaves it behind, so they all go into one that goes at the end (in memory where there is /dev/shm).
TMPDIR=$(mktemp -d /dev/shm/vkbook-fuzz.XXXXXX 2>/dev/null || mktemp -d)
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT

# The copies of the corpus and the logs of the last run stay in <build>/run/ for a look afterwards.
work=$build/run
rm -rf "$work"
mkdir -p "$work"
failed=0
for target in ${FUZZ_TARGETS:-obj scene gltf}; do
    corpus=$work/corpus-$target
    artifacts=$build/artifacts/$target
    cp -r "$here/corpus/$target" "$corpus"
    mkdir -p "$artifacts"
    before=$(find "$artifacts" -type f | wc -l)
    log=$work/$target.log
    dict=$here/dict
    [ -f "$here/dict-$target" ] && dict=$here/dict-$target
    echo "fuzz_$target: ${seconds} s over a copy of tests/reliability/fuzz/corpus/$target ($(find "$corpus" -type f | wc -l) inputs)"
    rc=0
    "$build/fuzz_$target" "$corpus" -dict="$dict" -max_total_time="$seconds" -timeout=5 \
        -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 -artifact_prefix="$artifacts/" \
        >"$log" 2>&1 || rc=$?
    status=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$status")
    ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$status")
    files=$(find "$corpus" -type f | wc -l)
    bytes=$(du -sb "$corpus" | cut -f1)
    found=$(($(find "$artifacts" -type f | wc -l) - before))
    echo "  runs ${runs:-?}, ${speed:-?} exec/s, cov ${cov:-?}, ft ${ft:-?}," \
         "corpus $files files / $bytes bytes, crashes/timeouts/leaks $found, exit code $rc"
    if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
        failed=1
        grep -E 'ERROR: |SUMMARY: |runtime error: |fuzz_[a-z]+: |==[0-9]+== ' "$log" | head -n 20 | sed 's/^/  | /'
        echo "  the input is in $artifacts/; reproduce with: $build/fuzz_$target FILE"
        continue
    fi
    if [ "$merge" -eq 1 ]; then
        "$build/fuzz_$target" -merge=1 -use_counters=0 -max_len=4096 -timeout=5 -rss_limit_mb=2048 \
            "$here/corpus/$target" "$corpus" >"$work/$target-merge.log" 2>&1
        echo "  merged into tests/reliability/fuzz/corpus/$target: $(find "$here/corpus/$target" -type f | wc -l) files," \
             "$(du -sb "$here/corpus/$target" | cut -f1) bytes"
    fi
done
exit "$failed"
