#!/usr/bin/env bash
# Run under tests/desktops/xvfb_run.sh: starts a chapter in a window, holds keys that move the lights (1, 4, Left)
# while it runs, and checks the chapter saw them, then closes it (Escape). With --validation on any
# validation message fails the run (exit 3).
#   window_keys.sh CHAPTER [chapter options...]
set -u
source "$(dirname "$0")/frames.sh"
chapter=$1
shift
out="${TMPDIR:-/tmp}/window_keys.$$.out"
"$chapter" "$@" > "$out" &
pid=$!
fail() { echo "window_keys: $*"; kill "$pid" 2> /dev/null; cat "$out"; rm -f "$out"; exit 1; }
window=$(timeout 60 xdotool search --sync --name "chapter-15") || fail "no window appeared"
window=${window%%$'\n'*}
xdotool mousemove --window "$window" 20 20  # keyboard focus follows the pointer without a window manager
# The window appears before the chapter's first frame has read its events: a key held meanwhile
# may not be seen. Its first frames ended, every key reaches it. Each key is held over 8 frames
# (the chapter reads the keys' state once a frame) and at least 0.7 s: the lights move by the
# time held, at most 0.1 s worth a frame, so the distance lies within the check's range on a fast
# machine (0.7 s or a little more) and on a loaded one (8 slow frames: 0.8 s worth at most).
wait_frames "$out" 2 || fail "no frames drawn"
for key in 1 4 Left; do
    xdotool keydown "$key"
    held_from=$(date +%s%N)
    wait_frames "$out" 8 || fail "no frames drawn while $key was held"
    while [ $(($(date +%s%N) - held_from)) -lt 700000000 ]; do sleep 0.05; done
    xdotool keyup "$key"
    wait_frames "$out" 1 || fail "no frames drawn after $key was released"
done
xdotool key --window "$window" Escape 2> /dev/null  # a BadWindow if the window closes before the release
wait_exit 60 || fail "it did not close within 60 s of Escape"
wait $pid
rc=$?
grep -v '^test-event: ' "$out"
grep -q "lights moved" "$out" || { echo "the key presses did not move the lights"; rc=1; }
rm -f "$out"
exit $rc
