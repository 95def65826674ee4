#!/usr/bin/env bash
# Run under xvfb-run: a window's life as a user lives it, with a window manager (jwm) so that
# minimising means what it means on a desktop. The chapter runs until closed, with --validation:
#   1. minimised for 2 s: it must stop drawing (almost no CPU time used meanwhile);
#   2. restored: it must draw again;
#   3. resized 100 times in a row to sizes all over the screen; its resident memory after the
#      10th and after the 100th resize (both back at the first size) must not grow by more than
#      LIMIT_KB: a swapchain or G-buffer leaked per resize would add megabytes each time (leaked
#      Vulkan objects of any size are the validation layer's to report, at exit). glibc's malloc
#      keeps freed large blocks in its heap once it has seen them freed (its mmap threshold
#      rises), which alone grows the heap by some 80 MB over these resizes with no leak at all;
#      MALLOC_MMAP_THRESHOLD_ pins the threshold, so large blocks go back to the system when freed
#      and what is left is what the program holds;
#   4. closed with Escape: exit 0 (a validation message would make it 3, the test's QUIET_STDERR
#      catches anything printed).
#   window_life.sh CHAPTER [chapter options...]
set -u
LIMIT_KB=${LIMIT_KB:-8192}
chapter=$1
shift
name=$(basename "$chapter")
out="${TMPDIR:-/tmp}/window_life.$$"

jwm > /dev/null 2>&1 &
wm=$!
MALLOC_MMAP_THRESHOLD_=131072 "$chapter" "$@" > "$out.stdout" 2> "$out.stderr" &
pid=$!
finish() {
    kill "$wm" 2> /dev/null
    cat "$out.stdout"
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
rss_kb() { awk '/^VmRSS/ { print $2 }' "/proc/$pid/status"; }
settled_rss_kb() {  # the least of three readings half a second apart: a leak stays, a transient goes
    local least=
    for _ in 1 2 3; do
        sleep 0.5
        local now
        now=$(rss_kb)
        [ -z "$least" ] || [ "$now" -lt "$least" ] && least=$now
    done
    echo "$least"
}
sleep 2

# 1-2. Minimise, measure, restore, measure.
xdotool windowminimize --sync "$window" || fail "xdotool could not minimise the window"
sleep 0.5
before=$(cpu_ticks)
sleep 2
minimised=$(($(cpu_ticks) - before))
xdotool windowmap --sync "$window"
xdotool windowactivate --sync "$window" 2> /dev/null
sleep 0.5
before=$(cpu_ticks)
sleep 1
restored=$(($(cpu_ticks) - before))
echo "minimised: ${minimised} ticks of CPU in 2 s; restored: ${restored} ticks in 1 s"
[ "$minimised" -le 10 ] || fail "it kept drawing while minimised"
[ "$restored" -ge 10 ] || fail "it did not draw again after being restored"

# 3. 100 resizes. The sizes walk over the screen in steps that do not repeat for a long while.
read -r width height < <(xdotool getwindowgeometry "$window" | awk '/Geometry/ { split($2, s, "x"); print s[1], s[2] }')
for i in $(seq 1 100); do
    w=$((160 + (i * 137) % 1100))
    h=$((90 + (i * 71) % 700))
    xdotool windowsize --sync "$window" "$w" "$h" 2> /dev/null || fail "resize $i to ${w}x${h} failed"
    sleep 0.05
    kill -0 "$pid" 2> /dev/null || fail "the chapter ended during resize $i"
    if [ "$i" -eq 10 ] || [ "$i" -eq 100 ]; then
        xdotool windowsize --sync "$window" "$width" "$height"
        sleep 0.5
        rss[$i]=$(settled_rss_kb)
    fi
done
growth=$((rss[100] - rss[10]))
echo "resident memory at ${width}x${height}: ${rss[10]} kB after 10 resizes, ${rss[100]} kB after 100 (${growth} kB more)"
[ "$growth" -le "$LIMIT_KB" ] || fail "memory grew by ${growth} kB over 90 resizes"

# 4. Close it as a user would.
xdotool key --window "$window" Escape
for _ in $(seq 1 100); do
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
done
kill -0 "$pid" 2> /dev/null && fail "it did not close within 10 s of Escape"
wait "$pid"
finish $?
