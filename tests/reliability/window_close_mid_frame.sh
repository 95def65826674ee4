#!/usr/bin/env bash
# window_close_mid_frame.sh CHAPTER ARGS...: a chapter in a window (with a window manager, jwm),
# drawing frames of more than a second, is closed with Escape in the middle of one: it must end
# within a second of the key, exit 0 (a closed window is the run's normal end), and say it was
# closed in the middle of a frame (common/core/stop.hpp).
set -u
chapter=$1
shift
name=$(basename "$chapter")
work=$(mktemp -d)
jwm > /dev/null 2>&1 &
wm=$!
trap 'kill "$wm" 2> /dev/null; rm -rf "$work"' EXIT
fail() { echo "window_close_mid_frame: $*" >&2; cat "$work/stderr" >&2; kill -9 "$pid" 2> /dev/null; exit 1; }
VKBOOK_TEST_EVENTS=1 "$chapter" "$@" > "$work/stdout" 2> "$work/stderr" &
pid=$!
window=$(timeout 60 xdotool search --sync --name "^$name") || fail "no window appeared"
window=${window%%$'\n'*}
# A few long frames ended (the presents have been seen to wait for them): the next one is drawing.
for _ in $(seq 1200); do
    grep -q '^test-event: frame 2 ended' "$work/stdout" && break
    kill -0 "$pid" 2> /dev/null || fail "the chapter ended early"
    sleep 0.1
done
grep -q '^test-event: frame 2 ended' "$work/stdout" || fail "no third frame within 120 s"
start=$(date +%s%N)
xdotool key --window "$window" Escape 2> /dev/null
wait "$pid"
status=$?
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
echo "window_close_mid_frame: exit $status ${elapsed_ms} ms after Escape"
cat "$work/stderr"
[ "$status" = 0 ] || fail "exit $status, expected 0"
grep -q "closed in the middle of a frame or a load; stopped after [0-9]* ms" "$work/stderr" || fail "no line saying so"
# The chapter's own stop, from the close to its line, within a second; the process's end after it
# is the system's, as soon as the process's threads get the CPU (seconds on a loaded machine).
stop_ms=$(sed -n 's/.*; stopped after \([0-9]*\) ms$/\1/p' "$work/stderr")
[ "$stop_ms" -lt 1000 ] || fail "it took $stop_ms ms to stop, more than a second"
# And the close was read in the middle of the frame, not at its end: the chapter reads the close
# while it waits for the frame, waits 0.4 s more for it, then cuts it short and says when (its
# wall-clock time, test-event: stop seen at N ms) -- within a second of the key press, well inside
# the frame of 1.4 s it would otherwise have waited out.
seen_ms=$(sed -n 's/^test-event: stop seen at \([0-9]*\) ms$/\1/p' "$work/stdout")
[ -n "$seen_ms" ] || fail "the chapter did not say when it saw the close"
seen_after=$((seen_ms - start / 1000000))
echo "window_close_mid_frame: the frame cut short ${seen_after} ms after Escape"
[ "$seen_after" -lt 1000 ] || fail "the frame was cut short $seen_after ms after Escape: the close was not read during it"
