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
frames=300
work=$(mktemp -d "${TMPDIR:-/tmp}/shadow_reload_walk.XXXXXX")
trap 'rm -rf "$work"; [ -n "${pid:-}" ] && kill "$pid" 2> /dev/null' EXIT
fail() {
    echo "shadow_reload_walk: $*"
    echo "--- chapter stdout"; cat "$work/stdout" 2> /dev/null
    echo "--- chapter stderr"; cat "$work/stderr" 2> /dev/null
    exit 1
}
options=(--device llvmpipe --validation --headless --width 320 --height 180 --frames "$frames"
         --camera-motion walk)
cp -rp "$shaders" "$work/shaders" || fail "cannot copy $shaders"
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" stdbuf -oL "$chapter" "${options[@]}" --shader-dir "$work/shaders" --screenshot "$out-scrolled.png" \
    > "$work/stdout" 2> "$work/stderr" &
pid=$!
# The edit once the frames have started (the chapter prints its scene when set up; stdbuf: line by
# line into the file). stdbuf preloads its library, which AddressSanitizer must be told to accept.
for _ in $(seq 300); do
    grep -q "^chapter-16: [0-9]* draws" "$work/stdout" 2> /dev/null && break
    sleep 0.1
done
sleep 1
frag=$work/shaders/chapter-16/shadow.frag
line='    outMoments = vec2(depth, depth * depth + 0.25 * (dx * dx + dy * dy));'
grep -qF "$line" "$frag" || fail "shadow.frag no longer has the line this test edits: $line"
sed -i 's/^    outMoments = vec2(depth, depth \* depth + 0.25 \* (dx \* dx + dy \* dy));$/    outMoments = vec2(depth, depth * depth + 0.25 * (dx * dx + dy * dy)) * 1.0;/' "$frag"
wait "$pid"
status=$?
pid=
[ "$status" = 0 ] || fail "the chapter exited with $status"
grep -q "^shaders: reloaded .*chapter-16/shadow.frag" "$work/stdout" ||
    fail "no reload of chapter-16/shadow.frag reported before frame $frames"
# The same walk without the reload: no cascade drawn whole fewer times, and at least one more
# whole drawing in all (one per cascade, unless the reload fell on a frame that drew it whole).
"$chapter" "${options[@]}" > "$work/plain" || fail "the walk without a reload failed"
whole() { sed -n 's/^chapter-16: cascades drawn .* (whole \(.*\))$/\1/p' "$1"; }
reloaded=$(whole "$work/stdout") plain=$(whole "$work/plain")
more=$(paste -d' ' <(tr ',' '\n' <<< "$reloaded") <(tr ',' '\n' <<< "$plain") |
    awk '$1 < $2 {bad = 1} {extra += $1 - $2} END {print (bad || extra < 1) ? "no" : "yes"}')
[ -n "$plain" ] && [ "$more" = yes ] ||
    fail "cascades drawn whole with the reload: $reloaded; without it: $plain (expected more)"
"$chapter" "${options[@]}" --shadow-redraw always --screenshot "$out-always.png" > /dev/null ||
    fail "the always-redrawn walk failed"
"$image_compare" "$out-scrolled.png" --size 320 180 --golden "$out-always.png" --max-diff 0 --max-fraction 0 ||
    fail "the last frame after the reload differs from the always-redrawn one"
echo "shadow_reload_walk: ok"
