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
window=$(timeout 60 xdotool search --sync --name "chapter-1") || { echo "no window appeared"; kill $pid; exit 1; }
window=${window%%$'\n'*}
sleep 4  # set-up done and a few frames drawn: the overlay is up, also in the sanitizer build
case $mode in
click)
    xdotool mousemove --window "$window" 27 241 click 1
    sleep 0.5
    xdotool mousemove --window "$window" 500 300  # away, so the box is not drawn hovered
    ;;
drag-overlay | drag-scene)
    if [ "$mode" = drag-overlay ]; then from=(60 60) to=(200 120); else from=(420 280) to=(560 330); fi
    xdotool mousemove --window "$window" "${from[@]}" mousedown 3
    for step in 1 2 3 4 5; do
        sleep 0.2
        xdotool mousemove --window "$window" $((from[0] + (to[0] - from[0]) * step / 5)) \
            $((from[1] + (to[1] - from[1]) * step / 5))
    done
    xdotool mouseup 3
    ;;
type-after-resize)
    xdotool windowsize "$window" 800 450
    sleep 1.5  # the swapchain is rebuilt for the new size
    # The Lights window hangs from the top right corner: its slider is 190 points from the right.
    # Dear ImGui 1.86 samples the keys' state once a frame: each key is held over a few frames.
    hold() { xdotool keydown "$1"; sleep 0.4; xdotool keyup "$1"; sleep 0.2; }
    xdotool mousemove --window "$window" 610 46 keydown ctrl
    sleep 0.4
    xdotool mousedown 1
    sleep 0.3
    xdotool mouseup 1
    sleep 0.3
    xdotool keydown a
    sleep 0.4
    xdotool keyup a keyup ctrl
    sleep 0.2
    hold BackSpace
    xdotool type 300
    hold Return
    ;;
f1)
    xdotool mousemove --window "$window" 500 300  # keyboard focus follows the pointer without a window manager
    xdotool keydown F1  # held over a few frames: the chapter polls the key's state each frame
    sleep 0.4
    xdotool keyup F1
    ;;
esac
sleep 0.5
xdotool mousemove --window "$window" 500 300 key Escape 2> /dev/null  # away from the overlay; Escape ends the run (a BadWindow if it closes before the release)
wait $pid
rc=$?
cat "$out"
case $mode in
drag-overlay) grep -q "camera moved" "$out" && { echo "a drag on the overlay moved the camera"; rc=1; } ;;
drag-scene) grep -q "camera moved" "$out" || { echo "a drag on the scene did not move the camera"; rc=1; } ;;
type-after-resize)
    grep -q "sun at 300.0 degrees" "$out" || { echo "the value typed into the overlay after a resize did not arrive"; rc=1; } ;;
esac
rm -f "$out"
exit $rc
