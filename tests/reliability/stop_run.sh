#!/usr/bin/env bash
# stop_run.sh CHAPTER MODE ARGS...: a run stopped by a signal in the middle of a long frame (MODE
# frame: SIGINT once the first frame has started) or of a long load (MODE load: SIGTERM half a
# second after start) ends within a second, with 130 or 143, one line on stderr, and leaves no
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
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" \
    stdbuf -oL "$chapter" "$@" > "$work/stdout" 2> "$work/stderr" &
pid=$!
if [ "$mode" = frame ]; then
    for _ in $(seq 600); do grep -q " draws, " "$work/stdout" 2> /dev/null && break; sleep 0.05; done
    grep -q " draws, " "$work/stdout" || fail "the chapter did not load"
    sleep 1.0  # inside a frame of several seconds
    signal=INT expected=130
else
    sleep 0.5
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
[ "$elapsed_ms" -lt 1000 ] || fail "it took $elapsed_ms ms to stop, more than a second"
[ "$(wc -l < "$work/stderr")" = 1 ] || fail "stderr is not one line"
grep -q "interrupted in the middle of a frame or a load; stopped" "$work/stderr" || fail "no line saying so"
leftovers=$(find "$cache" -name '*.tmp*' 2> /dev/null | wc -l)
[ "$leftovers" = 0 ] || fail "temporary files left in $cache: $(find "$cache" -name '*.tmp*')"
echo "stop_run: no temporary file left"
