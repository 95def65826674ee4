#!/usr/bin/env bash
# concurrent_runs.sh N RUNS -- COMMAND...: starts COMMAND N times at once, RUNS rounds one after
# the other, and fails unless every run exits 0 with nothing on stderr. For the pipeline cache,
# which every run of a chapter reads at start and replaces at exit: on Windows a file being
# replaced cannot be opened, nor one being read replaced, so both sides retry (common/vk/pipeline.cpp).
set -u
count=$1 rounds=$2
shift 3  # N RUNS --
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
for round in $(seq "$rounds"); do
    pids=()
    for i in $(seq "$count"); do
        "$@" > "$work/out-$round-$i" 2> "$work/err-$round-$i" &
        pids+=($!)
    done
    for i in $(seq "$count"); do
        if ! wait "${pids[$((i - 1))]}"; then
            echo "round $round, run $i: exit code not 0"
            failed=1
        fi
        if [ -s "$work/err-$round-$i" ]; then
            echo "round $round, run $i: stderr: $(head -c 300 "$work/err-$round-$i")"
            failed=1
        fi
    done
done
[ "$failed" -eq 0 ] && echo "concurrent_runs.sh: $rounds rounds of $count runs at once, all clean"
exit "$failed"
