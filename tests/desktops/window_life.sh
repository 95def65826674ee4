#!/usr/bin/env bash
# Run under tests/desktops/xvfb_run.sh: a window's life as a user lives it, with a window manager (jwm) so that
# minimising means what it means on a desktop. The chapter runs until closed, with --validation:
#   1. minimised for 3 s: it must stop drawing (at most the frame it was drawing ends meanwhile);
#   2. restored: it must draw again (frames end again, however slowly);
#   3. resized 100 times in a row to sizes all over the screen, and back at the first size after
#      every 10th, where its anonymous resident memory (RssAnon: the heap and the driver's images,
#      not shared or file pages) is read. The least-squares slope of those 10 readings must stay
#      under SLOPE_LIMIT_KB per resize: a swapchain or G-buffer leaked per resize adds 900 kB to
#      several MB each time. (Leaked Vulkan objects of any size are the validation layer's to
#      report, at exit.) The readings also move up and down by up to 21 MB with no leak at all --
#      the driver and the heap keep some memory from the sizes drawn last -- which alone gave
#      slopes of -131 to +106 kB per resize in trial runs; the limit is some three times that.
#      glibc's malloc keeps freed large blocks in its heap once it has seen them freed (its mmap
#      threshold rises), which grows the heap by some 80 MB over these resizes; the MALLOC_*
#      settings pin its thresholds, so freed memory goes back to the system;
#   4. closed with Escape: exit 0 (a validation message would make it 3, the test's QUIET_STDERR
#      catches anything printed).
#   window_life.sh CHAPTER [chapter options...]
set -u
source "$(dirname "$0")/frames.sh"
SLOPE_LIMIT_KB=${SLOPE_LIMIT_KB:-400}
chapter=$1
shift
name=$(basename "$chapter")
out="${TMPDIR:-/tmp}/window_life.$$"

jwm > /dev/null 2>&1 &
wm=$!
MALLOC_MMAP_THRESHOLD_=131072 MALLOC_TRIM_THRESHOLD_=131072 MALLOC_ARENA_MAX=1 "$chapter" "$@" > "$out.stdout" 2> "$out.stderr" &
pid=$!
finish() {
    kill "$wm" 2> /dev/null
    grep -v '^test-event: ' "$out.stdout"
    cat "$out.stderr" >&2
    rm -f "$out.stdout" "$out.stderr"
    exit "$1"
}
fail() {
    echo "window_life: $*"
    kill "$pid" 2> /dev/null
    finish 1
}

window=$(timeout 60 xdotool search --sync --name "^$name") || fail "no window appeared"
window=${window%%$'\n'*}
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$pid/stat"; }  # user + system time, 1/100 s
rss_kb() { awk '/^RssAnon/ { print $2 }' "/proc/$pid/status"; }
wait_frames "$out.stdout" 2 || fail "no frames drawn"  # its first frames

# 1-2. Minimise, measure, restore, wait for frames. Minimised, it waits for events: of the frames
# ended in the 3 s, at most the one it was drawing and the one it had begun (a chapter that kept
# drawing ends dozens even on a loaded machine). Its CPU time is reported, not checked: the frame
# it was drawing may take a second of it under the sanitizers.
xdotool windowminimize --sync "$window" || fail "xdotool could not minimise the window"
frames_before=$(frames_ended "$out.stdout")
ticks_before=$(cpu_ticks)
sleep 3  # a span in which nothing may happen: no event to wait for
minimised=$(($(frames_ended "$out.stdout") - frames_before))
ticks=$(($(cpu_ticks) - ticks_before))
xdotool windowmap --sync "$window"
xdotool windowactivate --sync "$window" 2> /dev/null
wait_frames "$out.stdout" 3 || fail "it did not draw again after being restored"
echo "minimised: ${minimised} frames ended and ${ticks} ticks of CPU in 3 s; restored: drawing again"
[ "$minimised" -le 2 ] || fail "it kept drawing while minimised"

# 3. 100 resizes. The sizes walk over the screen in steps that do not repeat for a long while.
read -r width height < <(xdotool getwindowgeometry "$window" | awk '/Geometry/ { split($2, s, "x"); print s[1], s[2] }')
readings=""
for i in $(seq 1 100); do
    w=$((160 + (i * 137) % 1100))
    h=$((90 + (i * 71) % 700))
    xdotool windowsize --sync "$window" "$w" "$h" 2> /dev/null || fail "resize $i to ${w}x${h} failed"
    sleep 0.05
    kill -0 "$pid" 2> /dev/null || fail "the chapter ended during resize $i"
    if [ $((i % 10)) -eq 0 ]; then
        xdotool windowsize --sync "$window" "$width" "$height"
        wait_frames "$out.stdout" 3 || fail "no frames drawn after resize $i"  # at that size, the old size's images gone
        readings="$readings $(rss_kb)"
    fi
done
# Least-squares slope of the readings against the resize count (10, 20, ... 100).
slope=$(echo "$readings" | awk '{ for (i = 1; i <= NF; ++i) { x = 10 * i; sx += x; sy += $i; sxx += x * x; sxy += x * $i }
                                  printf "%d", (NF * sxy - sx * sy) / (NF * sxx - sx * sx) }')
echo "anonymous resident memory at ${width}x${height} after every 10th resize (kB):${readings}"
echo "resident memory slope over 100 resizes: ${slope} kB per resize (limit ${SLOPE_LIMIT_KB})"
[ "$slope" -le "$SLOPE_LIMIT_KB" ] || fail "memory grew by ${slope} kB per resize"

# 4. Close it as a user would. The chapter may close the window on the key press, before xdotool
# sends the release: X then reports a BadWindow to xdotool, which is no failure of the chapter
# (whether it closed is checked next).
xdotool key --window "$window" Escape 2> /dev/null
wait_exit 60 || fail "it did not close within 60 s of Escape"
wait "$pid"
finish $?
