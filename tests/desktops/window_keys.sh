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
