#!/usr/bin/env bash
# chapter-16's shadow cache across a live reload mid-walk: the chapter walks (--camera-motion walk,
# the default --shadow-redraw scrolled) with --shader-dir on a copy of the shader sources; while it
# runs, the shadow pass's fragment shader is edited so that its code changes and what it computes
# does not (the moments times 1.0). The reload must be reported before the last frame, the
# cascades drawn whole more often than without the reload, and the last frame must equal the one
# the same walk draws with every cascade drawn every frame.
#
#   shadow_reload_walk.sh SHADERS CHAPTER IMAGE_COMPARE OUT_PREFIX
set -u
shaders=$1 chapter=$2 image_compare=$3 out=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/shadow_reload_walk.XXXXXX")
trap 'rm -rf "$work"; [ -n "${pid:-}" ] && kill "$pid" 2> /dev/null' EXIT
fail() {
    echo "shadow_reload_walk: $*"
    echo "--- chapter stdout"; grep -v '^test-event: ' "$work/stdout" 2> /dev/null
    echo "--- chapter stderr"; cat "$work/stderr" 2> /dev/null
    exit 1
}
# Waits up to 300 s for the COUNT-th line matching PATTERN in the chapter's stdout.
wait_for() {
    local pattern=$1 count=${2:-1}
    for _ in $(seq 3000); do
        [ "$(grep -c -- "$pattern" "$work/stdout" 2> /dev/null)" -ge "$count" ] && return 0
        kill -0 "$pid" 2> /dev/null || fail "the chapter ended while waiting for '$pattern'"
        sleep 0.1
    done
    fail "no '$pattern' (x$count) within 300 s"
}
options=(--device llvmpipe --validation --headless --width 320 --height 180 --camera-motion walk)
cp -rp "$shaders" "$work/shaders" || fail "cannot copy $shaders"
# Walks until stopped (Ctrl+C, as a reader would), each frame's end a line (VKBOOK_TEST_EVENTS):
# the edit, the reload and the stop follow the frames, not a guessed time. stdbuf: line by line
# into the file; it preloads its library, which AddressSanitizer must be told to accept.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" VKBOOK_TEST_EVENTS=1 VKBOOK_STOP_GRACE_MS=20000 \
    stdbuf -oL "$chapter" "${options[@]}" --frames 10000000 --shader-dir "$work/shaders" --screenshot "$out-scrolled.png" \
    > "$work/stdout" 2> "$work/stderr" &
pid=$!
# The edit once the walk has begun (its cascades drawn and scrolled for some frames).
wait_for "^test-event: frame 10 ended"
frag=$work/shaders/chapter-16/shadow.frag
line='    outMoments = vec2(depth, depth * depth + 0.25 * (dx * dx + dy * dy));'
grep -qF "$line" "$frag" || fail "shadow.frag no longer has the line this test edits: $line"
sed -i 's/^    outMoments = vec2(depth, depth \* depth + 0.25 \* (dx \* dx + dy \* dy));$/    outMoments = vec2(depth, depth * depth + 0.25 * (dx * dx + dy * dy)) * 1.0;/' "$frag"
wait_for "^shaders: reloaded .*chapter-16/shadow.frag"
# Twenty frames walked with the new pipelines, the cascades scrolled again after their redrawing.
wait_for "^test-event: frame " "$(($(grep -c '^test-event: frame ' "$work/stdout") + 20))"
kill -INT "$pid"
wait "$pid"
status=$?
pid=
[ "$status" = 0 ] || fail "the chapter exited with $status"
frames=$(sed -n 's/^chapter-16: cascades drawn .* in \([0-9]*\) frames.*$/\1/p' "$work/stdout")
[ -n "$frames" ] || fail "no count of frames reported"
echo "shadow_reload_walk: the reload came before frame $frames"
# The same walk of as many frames without the reload: no cascade drawn whole fewer times, and at
# least one more whole drawing in all (one per cascade, unless the reload fell on a frame that
# drew it whole).
"$chapter" "${options[@]}" --frames "$frames" > "$work/plain" || fail "the walk without a reload failed"
whole() { sed -n 's/^chapter-16: cascades drawn .* (whole \(.*\))$/\1/p' "$1"; }
reloaded=$(whole "$work/stdout") plain=$(whole "$work/plain")
more=$(paste -d' ' <(tr ',' '\n' <<< "$reloaded") <(tr ',' '\n' <<< "$plain") |
    awk '$1 < $2 {bad = 1} {extra += $1 - $2} END {print (bad || extra < 1) ? "no" : "yes"}')
[ -n "$plain" ] && [ "$more" = yes ] ||
    fail "cascades drawn whole with the reload: $reloaded; without it: $plain (expected more)"
"$chapter" "${options[@]}" --frames "$frames" --shadow-redraw always --screenshot "$out-always.png" > /dev/null ||
    fail "the always-redrawn walk failed"
"$image_compare" "$out-scrolled.png" --size 320 180 --golden "$out-always.png" --max-diff 0 --max-fraction 0 ||
    fail "the last frame after the reload differs from the always-redrawn one"
echo "shadow_reload_walk: ok"
