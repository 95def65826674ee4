#!/usr/bin/env bash
# Run under tests/desktops/xvfb_run.sh: starts a chapter in a window, holds keys that move the lights (1, 4, Left)
# while it runs, and checks the chapter saw them. The chapter also resizes itself half-way
# (--resize), with --validation on: any validation message fails the run (exit 3).
#   window_keys.sh CHAPTER [chapter options...]
set -u
chapter=$1
shift
"$chapter" "$@" > "${TMPDIR:-/tmp}/window_keys.$$.out" &
pid=$!
window=$(timeout 60 xdotool search --sync --name "chapter-15") || { echo "no window appeared"; kill $pid; exit 1; }
window=${window%%$'\n'*}
xdotool mousemove --window "$window" 20 20  # keyboard focus follows the pointer without a window manager
# The window appears before the chapter's first frame has read its events; on a busy machine (the
# suite runs three tests at once on two cores) that can take a second or more, and a key held
# meanwhile was not always seen. Its first frames drawn, every key reaches it.
sleep 2
for key in 1 4 Left; do
    xdotool keydown "$key"
    sleep 0.7
    xdotool keyup "$key"
done
wait $pid
rc=$?
cat "${TMPDIR:-/tmp}/window_keys.$$.out"
grep -q "lights moved" "${TMPDIR:-/tmp}/window_keys.$$.out" || { echo "the key presses did not move the lights"; rc=1; }
rm -f "${TMPDIR:-/tmp}/window_keys.$$.out"
exit $rc
