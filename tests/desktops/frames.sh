# Sourced by the scripts that drive a chapter in a window: waiting for the chapter's frames instead
# of sleeping for a guessed time. The chapter runs with VKBOOK_TEST_EVENTS=1 (each frame's end is a
# line "test-event: frame N ended" on its stdout, common/app/run_control.cpp) and its stdout in a
# file; $pid is the chapter's process. A key or button held until some frames have ended is seen
# by the chapter (it reads the keys' state once a frame), however slow those frames are.
export VKBOOK_TEST_EVENTS=1
# A stop (Escape, Ctrl+C) lets the frame being drawn end, its screenshot written, however slow it
# is on a loaded machine (a reader gets 0.4 s, common/core/stop.cpp).
export VKBOOK_STOP_GRACE_MS=20000

# frames_ended FILE: how many frames the chapter has ended so far.
frames_ended() { grep -c '^test-event: frame ' "$1" 2> /dev/null; }
# wait_frames FILE N: waits until N more frames have ended than when called (at most 120 s, and
# only while the chapter runs); returns 1 when they did not.
wait_frames() {
    local file=$1 target
    target=$(($(frames_ended "$file") + $2))
    for _ in $(seq 1200); do
        [ "$(frames_ended "$file")" -ge "$target" ] && return 0
        kill -0 "$pid" 2> /dev/null || return 1
        sleep 0.1
    done
    return 1
}
# wait_exit SECONDS: waits for the chapter to end; returns 1 when it still runs.
wait_exit() {
    for _ in $(seq $(($1 * 10))); do
        kill -0 "$pid" 2> /dev/null || return 0
        sleep 0.1
    done
    return 1
}
