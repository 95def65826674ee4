#!/usr/bin/env bash
# stop_run.sh CHAPTER MODE ARGS...: a run stopped by a signal in the middle of a long frame (MODE
# frame: SIGINT once the first frame has ended) or of a long load (MODE load: SIGTERM once the
# model's load has begun) stops within a second (what its line says), with 130 or 143, one line on stderr, and leaves no
# temporary file of the pipeline cache behind. MODE stale: a temporary left beside the cache by a
# process that no longer runs (killed with SIGKILL halfway through writing it) is removed by the
# next run that saves the cache.
set -u
chapter=$1 mode=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "stop_run: $*" >&2; exit 1; }
export XDG_CACHE_HOME="$work/cache"  # its own: other tests write theirs meanwhile
cache="$XDG_CACHE_HOME/vulkan-book-cpp"
if [ "$mode" = stale ]; then
    "$chapter" "$@" > /dev/null 2>&1 || fail "the first run failed"
    file=$(find "$cache" -name "$(basename "$chapter")-*.bin" | head -1)
    [ -n "$file" ] || fail "no pipeline cache of $(basename "$chapter") in $cache"
    stale="$file.tmp2147483646"  # a process id beyond any pid_max: no such process
    echo "stale" > "$stale"
    "$chapter" "$@" > /dev/null 2>&1 || fail "the second run failed"
    [ -e "$stale" ] && fail "$stale is still there"
    echo "stop_run: the stale temporary $(basename "$stale") was removed"
    exit 0
fi
# stdbuf: its lines as printed. It preloads a library of its own, which AddressSanitizer would
# refuse to follow (the sanitizer build): its order check is turned off for this run.
# VKBOOK_TEST_EVENTS: the chapter says when its stop handlers are in place and when each frame
# ends, so that the signal is sent after an event, never after a guessed time.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" VKBOOK_TEST_EVENTS=1 \
    stdbuf -oL "$chapter" "$@" > "$work/stdout" 2> "$work/stderr" &
pid=$!
wait_line() {  # wait_line PATTERN: up to 120 s, while the chapter runs
    for _ in $(seq 1200); do
        grep -q "$1" "$work/stdout" 2> /dev/null && return 0
        kill -0 "$pid" 2> /dev/null || fail "the chapter ended before '$1': $(cat "$work/stderr")"
        sleep 0.1
    done
    fail "no '$1' within 120 s"
}
if [ "$mode" = frame ]; then
    wait_line '^test-event: frame 0 ended'  # the next frame, of several seconds, is being drawn
    signal=INT expected=130
else
    wait_line '^test-event: loading '  # the model's load, of several seconds, has begun
    signal=TERM expected=143
fi
kill -0 "$pid" 2> /dev/null || fail "the chapter ended before the signal: $(cat "$work/stderr")"
start=$(date +%s%N)
kill -"$signal" "$pid"
wait "$pid"
status=$?
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
echo "stop_run: exit $status ${elapsed_ms} ms after SIG$signal"
cat "$work/stderr"
[ "$status" = "$expected" ] || fail "exit $status, expected $expected"
[ "$(wc -l < "$work/stderr")" = 1 ] || fail "stderr is not one line"
grep -q "interrupted in the middle of a frame or a load; stopped after [0-9]* ms" "$work/stderr" || fail "no line saying so"
# The chapter's own stop, from the signal to its line, within a second; the process's end after it
# is the system's, as soon as the process's threads get the CPU (seconds on a loaded machine).
stop_ms=$(sed -n 's/.*; stopped after \([0-9]*\) ms$/\1/p' "$work/stderr")
[ "$stop_ms" -lt 1000 ] || fail "it took $stop_ms ms to stop, more than a second"
leftovers=$(find "$cache" -name '*.tmp*' 2> /dev/null | wc -l)
[ "$leftovers" = 0 ] || fail "temporary files left in $cache: $(find "$cache" -name '*.tmp*')"
echo "stop_run: no temporary file left"
