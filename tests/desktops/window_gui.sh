#!/usr/bin/env bash
# Run under tests/desktops/xvfb_run.sh: the --gui overlay in a real window, driven by xdotool.
#   window_gui.sh click CHAPTER OUT.png [options...]   clicks the overlay's FXAA box (at 27,241 in the
#                                                    window): the last frame's screenshot must show it
#                                                    ticked (the caller checks the pixel)
#   window_gui.sh drag-overlay CHAPTER [options...]    right-drags across the overlay: the camera must
#                                                    not move
#   window_gui.sh drag-scene CHAPTER [options...]      right-drags across the scene, away from the
#                                                    overlay: the camera must move (the check above can
#                                                    fail)
#   window_gui.sh f1 CHAPTER OUT.png [options...]      presses F1: the last frame has no overlay
#   window_gui.sh type-after-resize CHAPTER [options...]  resizes the window (as a user would, through
#                                                    the window system), then Ctrl+clicks chapter-15's
#                                                    "sun angle" slider, which makes it a text field,
#                                                    selects its text (Ctrl+A), deletes it
#                                                    (Backspace), types 300 and Enter, and closes the
#                                                    window (Escape): the chapter must report the sun
#                                                    at 300 degrees. Every key but the digits is one
#                                                    that only reaches the overlay through the key
#                                                    callback Dear ImGui chains to ours.
# The chapter runs with --validation: any validation message fails it (exit 3). It runs until the
# script closes the window (Escape) when it is done: no frame count to outrun on a slow machine
# (the sanitizer build under load draws a frame in a second or more), and the screenshot is of
# the last frame, after everything the script did.
set -u
source "$(dirname "$0")/frames.sh"
mode=$1
chapter=$2
shift 2
shot=""
if [ "$mode" = click ] || [ "$mode" = f1 ]; then
    shot=$1
    shift
    set -- "$@" --screenshot "$shot"
fi
out=${TMPDIR:-/tmp}/window_gui.$$.out
"$chapter" "$@" > "$out" &
pid=$!
fail() { echo "window_gui: $*"; kill "$pid" 2> /dev/null; grep -v '^test-event: ' "$out"; rm -f "$out"; exit 1; }
window=$(timeout 60 xdotool search --sync --name "chapter-1") || fail "no window appeared"
window=${window%%$'\n'*}
# Set-up done and a few frames drawn: the overlay is up. Every step below waits for frames, not
# for a time: the chapter reads the pointer and the keys once a frame.
frames() { wait_frames "$out" "$1" || fail "no frames drawn"; }
frames 3
case $mode in
click)
    xdotool mousemove --window "$window" 27 241
    frames 2  # hovered
    xdotool mousedown 1
    frames 2
    xdotool mouseup 1
    frames 2
    xdotool mousemove --window "$window" 500 300  # away, so the box is not drawn hovered
    ;;
drag-overlay | drag-scene)
    if [ "$mode" = drag-overlay ]; then from=(60 60) to=(200 120); else from=(420 280) to=(560 330); fi
    xdotool mousemove --window "$window" "${from[@]}" mousedown 3
    for step in 1 2 3 4 5; do
        frames 1
        xdotool mousemove --window "$window" $((from[0] + (to[0] - from[0]) * step / 5)) \
            $((from[1] + (to[1] - from[1]) * step / 5))
    done
    frames 2
    xdotool mouseup 3
    ;;
type-after-resize)
    xdotool windowsize --sync "$window" 800 450
    frames 3  # the swapchain rebuilt for the new size, and drawn at it
    # The Lights window hangs from the top right corner: its slider is 190 points from the right.
    # Dear ImGui 1.86 samples the keys' state once a frame: each key is held over frames.
    hold() { xdotool keydown "$1"; frames 2; xdotool keyup "$1"; frames 1; }
    xdotool mousemove --window "$window" 610 46 keydown ctrl
    frames 2
    xdotool mousedown 1
    frames 2
    xdotool mouseup 1
    frames 2
    xdotool keydown a
    frames 2
    xdotool keyup a keyup ctrl
    frames 1
    hold BackSpace
    # Typed, not held: a key held past the X server's repeat delay would repeat. Dear ImGui
    # queues typed characters, so they need no frames of their own.
    xdotool type --delay 100 300
    frames 2
    hold Return
    ;;
f1)
    xdotool mousemove --window "$window" 500 300  # keyboard focus follows the pointer without a window manager
    xdotool keydown F1  # held over a few frames: the chapter polls the key's state each frame
    frames 2
    xdotool keyup F1
    ;;
esac
frames 2
xdotool mousemove --window "$window" 500 300 key Escape 2> /dev/null  # away from the overlay; Escape ends the run (a BadWindow if it closes before the release)
wait_exit 60 || fail "it did not close within 60 s of Escape"
wait $pid
rc=$?
grep -v '^test-event: ' "$out"
case $mode in
drag-overlay) grep -q "camera moved" "$out" && { echo "a drag on the overlay moved the camera"; rc=1; } ;;
drag-scene) grep -q "camera moved" "$out" || { echo "a drag on the scene did not move the camera"; rc=1; } ;;
type-after-resize)
    grep -q "sun at 300.0 degrees" "$out" || { echo "the value typed into the overlay after a resize did not arrive"; rc=1; } ;;
esac
rm -f "$out"
exit $rc
