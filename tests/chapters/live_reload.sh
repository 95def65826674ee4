#!/usr/bin/env bash
# Live shader reload as a reader does it: a chapter runs with --shader-dir pointing at a copy of
# the shader sources, the test edits a shader while it runs, and the last frame (--screenshot)
# must show what the edit says.
#
#   live_reload.sh SCENARIO SHADERS SHADER IMAGE_COMPARE CHAPTER [options...]
#
# SHADERS is the source tree's shaders/ (copied to a temporary directory), SHADER the file to edit
# in it (e.g. chapter-15/light.frag; its main() writes outColor), or FILE=NAME when the program
# loads it under another name (a variant or another chapter's: chapter-15-lab/light-book.frag). Every edit puts one line before
# the file's last '}'. Headless when the options say --headless (the run is ended by SIGINT, as
# Ctrl+C would), else in a window under Xvfb (ended by Escape). SCENARIO:
#   edit       outColor = magenta: the reload is reported, and the last frame equals a frame
#              rendered from the start with the edited shader, and differs from the unedited one;
#   broken     the line has a syntax error: the error names the file and the line, the running
#              pipelines stay (the last frame equals the unedited one; with --gui it differs from
#              it: the overlay shows the error);
#   fix        broken, then the line corrected: the fix is picked up (the last frame is the edit's);
#   interface  the shader reads a descriptor its pipeline layout does not have: refused as an
#              interface change, the running pipelines stay;
#   accept     a safe interface change ($RULE: tests/chapters/live_reload_rules.py's accept-*) with the
#              edit's magenta line: reloaded, never refused, the last frame is the edit's;
#   rule       an interface change of the kind $RULE names (tests/chapters/live_reload_rules.py), saved by
#              renaming: refused with the rule's message, the running pipelines stay;
#   fault      the edit of 'edit', but the reload's FAULT_OFFSET-th pipeline (default the first)
#              fails to be made (VKBOOK_FAULT=vkCreate<PIPELINE_KIND>Pipelines:n+FAULT_OFFSET of the
#              fault-injection layer, n the pipelines made at start-up): refused, the old pipelines
#              keep drawing; then RETOUCH (another shader file; default the edited one) is saved,
#              and the edit is picked up with it (the last frame is the edit's);
#   save-STYLE the edit of 'edit' saved as an editor does (tests/chapters/live_reload_save.py: in-place,
#              truncate, rename-new, rename-old, delete), with pauses between the steps so that a
#              poll may see the file in between: picked up, the chapter never ends (a step in
#              between is at most a reported error);
#   during-compile  every compile made slow (VKBOOK_TEST_COMPILE_DELAY_MS), a second edit saved
#              while the first one compiles: both picked up, the last frame is the second's;
#   leak       the edited file touched RELOADS times (default 50), each a full reload; the anonymous
#              resident memory is read every 5th and its least-squares slope must stay under
#              SLOPE_LIMIT_KB per reload (tests/desktops/window_life.sh's method); the exit code covers
#              leaked Vulkan objects (--validation reports them at exit).
# With EXPECT_PIPELINES=N (and the fault-injection layer loaded, VKBOOK_FAULT_LAYER=1), the reload
# must make exactly N pipelines (vkCreateGraphicsPipelines and vkCreateComputePipelines calls,
# counted by the layer's VKBOOK_FAULT_TRACE): only those whose shaders the edit changed.
# Exit code 0 when all holds; the chapter's own exit code must be 0 (with --validation: no message).
set -u
scenario=$1 shaders=$2 shader=${3%%=*} shader_name=${3#*=} image_compare=$4 chapter=$5
shift 5
RELOADS=${RELOADS:-50}
SLOPE_LIMIT_KB=${SLOPE_LIMIT_KB:-400}
headless=0 gui=0
for arg in "$@"; do
    [ "$arg" = --headless ] && headless=1
    [ "$arg" = --gui ] && gui=1
done
name=$(basename "$chapter")
work=$(mktemp -d "${TMPDIR:-/tmp}/live_reload.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
    echo "live_reload: $*"
    [ -n "${pid:-}" ] && kill "$pid" 2> /dev/null
    echo "--- chapter stdout"; cat "$work/stdout" 2> /dev/null
    echo "--- chapter stderr"; cat "$work/stderr" 2> /dev/null
    exit 1
}

# The copy keeps the sources' times (-p), older than the build's SPIR-V: the chapter starts with the
# build's code, as a reader's run does, and compiles only what the test then edits.
cp -rp "$shaders" "$work/edited" || fail "cannot copy $shaders"
target="$work/edited/$shader"
[ -f "$target" ] || fail "no $shader in $shaders"
good=${GOOD:-'    outColor = vec4(1.0, 0.0, 1.0, 1.0);  // live_reload.sh'}  # GOOD: another shader's output
second='    outColor = vec4(0.0, 1.0, 1.0, 1.0);  // live_reload.sh'
broken='    outColor = vec4(1.0, 0.0, 1.0 1.0);  // live_reload.sh'
interface='    outColor = liveReloadExtra.color;  // live_reload.sh'
# The test's own edits are saved whole (written next to the file, then renamed over it): a file
# emptied and then written may be read between the two, and the compile error that follows is not
# what the scenario checks (the save-* scenarios try each way an editor saves).
# Puts LINE before the last '}' of the file (a new line of its own); prints its line number.
insert() {
    python3 - "$target" "$1" << 'EOF'
import os, sys
path, line = sys.argv[1], sys.argv[2]
text = open(path).read()
end = text.rindex('}')
start = text.rindex('\n', 0, end) + 1
with open(path + '.saving', 'w') as f:
    f.write(text[:start] + line + '\n' + text[start:])
os.replace(path + '.saving', path)
print(text[:start].count('\n') + 1)
EOF
}
# Replaces the line inserted before.
replace() {
    python3 - "$target" "$1" << 'EOF'
import os, sys
path, line = sys.argv[1], sys.argv[2]
lines = open(path).read().split('\n')
lines = [line if l.endswith('// live_reload.sh') else l for l in lines]
with open(path + '.saving', 'w') as f:
    f.write('\n'.join(lines))
os.replace(path + '.saving', path)
EOF
}
# Waits up to 60 s for a line matching PATTERN in FILE; COUNT-th match (default 1); GREP_FLAG -E
# for an extended regular expression.
wait_for() {
    local file=$1 pattern=$2 count=${3:-1} flag=${4:--G}
    for _ in $(seq 600); do
        [ "$(grep -c "$flag" -- "$pattern" "$file" 2> /dev/null)" -ge "$count" ] && return 0
        kill -0 "$pid" 2> /dev/null || fail "the chapter ended while waiting for '$pattern'"
        sleep 0.1
    done
    fail "no '$pattern' (x$count) within 60 s"
}

# The references, rendered headless from the start: the unedited shaders and the edited one.
# DIR "build": the build's SPIR-V of the same unedited sources (nothing compiled at start-up).
reference() {  # reference DIR OUT.png (compiled at full speed: the delay is the live run's)
    local shader_dir=(--shader-dir "$1")
    [ "$1" = build ] && shader_dir=()
    env -u VKBOOK_TEST_COMPILE_DELAY_MS "$chapter" "${chapter_options[@]}" --headless --frames 1 "${shader_dir[@]}" --screenshot "$2" \
        > /dev/null 2> "$work/reference.stderr" || fail "reference run failed: $(cat "$work/reference.stderr")"
}
chapter_options=()
for arg in "$@"; do [ "$arg" != --headless ] && [ "$arg" != --validation ] && chapter_options+=("$arg"); done

# The run.
if [ "$scenario" = fault ]; then
    # How many pipelines the chapter makes at start-up, so that the reload's first one fails.
    call=vkCreate${PIPELINE_KIND:-Graphics}Pipelines
    made=$(VKBOOK_FAULT_TRACE=1 "$chapter" "${chapter_options[@]}" --validation --headless --frames 1 --shader-dir "$work/edited" \
        2>&1 > /dev/null | grep -c "fault_injection: $call #")
    [ "$made" -gt 0 ] || fail "the fault-injection layer is not loaded (no $call counted)"
    export VKBOOK_FAULT=$call:$((made + ${FAULT_OFFSET:-1}))
fi
if [ -n "${EXPECT_PIPELINES:-}" ]; then
    made=$(VKBOOK_FAULT_TRACE=1 "$chapter" "${chapter_options[@]}" --validation --headless --frames 1 --shader-dir "$work/edited" \
        2>&1 > /dev/null | grep -cE "fault_injection: vkCreate(Graphics|Compute)Pipelines #")
    [ "$made" -gt 0 ] || fail "the fault-injection layer is not loaded (no pipeline counted)"
    export VKBOOK_FAULT_TRACE=1
fi
run_options=(--shader-dir "$work/edited" --screenshot "$work/last.png")
[ $headless = 1 ] && run_options+=(--frames 10000000)
MALLOC_MMAP_THRESHOLD_=131072 MALLOC_TRIM_THRESHOLD_=131072 MALLOC_ARENA_MAX=1 VKBOOK_STOP_GRACE_MS=20000 \
    VKBOOK_TEST_EVENTS=1 "$chapter" "$@" "${run_options[@]}" > "$work/stdout" 2> "$work/stderr" &
pid=$!
if [ $headless = 0 ]; then
    window=$(timeout 60 xdotool search --sync --name "^$name") || fail "no window appeared"
    window=${window%%$'\n'*}
fi
# Its first frames ended: every shader it draws with has been loaded (and its files are watched).
wait_for "$work/stdout" "^test-event: frame 1 ended"
rss_kb() { awk '/^RssAnon/ { print $2 }' "/proc/$pid/status"; }

case $scenario in
edit)
    insert "$good" > /dev/null
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it"
    ;;
broken)
    line=$(insert "$broken")
    wait_for "$work/stderr" "did not reload"
    grep -q -- "$shader:$line: error" "$work/stderr" || fail "the error does not name $shader:$line"
    ;;
fix)
    line=$(insert "$broken")
    wait_for "$work/stderr" "did not reload"
    grep -q -- "$shader:$line: error" "$work/stderr" || fail "the error does not name $shader:$line"
    sleep 0.5  # the file's time must differ from the broken one's
    replace "$good"
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it"
    ;;
interface)
    # Edited in a copy and renamed over the file, as many editors save: one change.
    cp "$target" "$work/staged"
    edited_file=$target
    target=$work/staged
    python3 - "$target" << 'EOF'
import sys
path = sys.argv[1]
text = open(path).read()
at = text.index('layout(location = 0) out vec4 outColor;')
open(path, 'w').write(text[:at] + 'layout(set = 6, binding = 0) uniform LiveReloadExtra { vec4 color; } liveReloadExtra;\n' + text[at:])
EOF
    insert "$interface" > /dev/null
    target=$edited_file
    mv "$work/staged" "$target"
    wait_for "$work/stderr" "did not reload"
    grep -q "interface changed: it uses set 6 binding 0 (uniform block LiveReloadExtra), which the shader its pipeline was made for does not declare" \
        "$work/stderr" || fail "not reported as an interface change"
    ;;
accept)
    [ "$(python3 "$(dirname "$0")/live_reload_rules.py" "$work/edited" "${RULE:-}")" = ACCEPTED ] ||
        fail "rule '${RULE:-}' is not an accepted change"
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it"
    grep -q "did not reload" "$work/stderr" && fail "refused: $(grep 'did not reload' "$work/stderr")"
    ;;
rule)
    expected=$(python3 "$(dirname "$0")/live_reload_rules.py" "$work/edited" "${RULE:-}") ||
        fail "rule '${RULE:-}' could not be applied"
    # The rule's message, however the saves fall between polls (an include saved first may be
    # compiled on its own, and the rest at a later poll): waited for, not timed.
    wait_for "$work/stderr" "$expected" 1 -E
    ;;
save-*)
    python3 "$(dirname "$0")/live_reload_save.py" "$target" "$good" "${scenario#save-}" ||
        fail "save style ${scenario#save-} failed"
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it"
    sleep 0.6  # what a later poll makes of it: still the edit
    ;;
during-compile)
    compiles=$(grep -c "^test-event: compiling .*$shader_name" "$work/stdout")
    insert "$good" > /dev/null
    # The edited file read and its compile begun (VKBOOK_TEST_COMPILE_DELAY_MS makes it slow):
    # the second edit lands during it.
    wait_for "$work/stdout" "^test-event: compiling .*$shader_name" $((compiles + 1))
    replace "$second"
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it" 2
    ;;
fault)
    insert "$good" > /dev/null
    wait_for "$work/stderr" "did not reload"
    grep -q "did not reload: .*VK_ERROR_OUT_OF_DEVICE_MEMORY" "$work/stderr" || fail "the failure is not reported"
    grep -q "^shaders: reloaded" "$work/stdout" && fail "reported as reloaded"
    sleep 0.5
    # Another file saved ($RETOUCH, a shader of the chapter; the edited one by default): the
    # failed reload's shaders are compiled again with it, and this time the pipelines are made.
    touch "$work/edited/${RETOUCH:-$shader}"
    wait_for "$work/stdout" "^shaders: reloaded .*first frame with it"
    ;;
leak)
    readings=()
    for i in $(seq "$RELOADS"); do
        touch "$target"  # a new time: the same code, reloaded
        wait_for "$work/stdout" "^shaders: reloaded .*first frame with it" "$i"
        if [ $((i % 5)) = 0 ]; then
            sleep 0.3
            readings+=("$(rss_kb)")
        fi
    done
    slope=$(printf '%s\n' "${readings[@]}" | awk '{ x = NR * 5; sx += x; sy += $1; sxx += x * x; sxy += x * $1; n++ }
        END { printf "%d", (n * sxy - sx * sy) / (n * sxx - sx * sx) }')
    echo "resident memory over $RELOADS reloads: ${readings[*]} kB; slope $slope kB per reload"
    # CHECK_MEMORY=0: the reloads for another purpose (the names test; memory is the .leak tests').
    [ "${CHECK_MEMORY:-1}" = 0 ] || [ "$slope" -lt "$SLOPE_LIMIT_KB" ] ||
        fail "resident memory grows by $slope kB per reload"
    ;;
*) fail "unknown scenario '$scenario'" ;;
esac
# A few frames with the outcome (frames, not a time: a loaded machine draws them slowly).
wait_for "$work/stdout" "^test-event: frame " $(($(grep -c '^test-event: frame ' "$work/stdout") + 3))

if [ $headless = 1 ]; then
    kill -INT "$pid"
else
    xdotool key --window "$window" Escape 2> /dev/null  # a BadWindow if the window closes before the release
fi
for _ in $(seq 300); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
kill -0 "$pid" 2> /dev/null && fail "the chapter did not end"
wait "$pid"
status=$?
# 0: it ended at a frame's end, its last frame written (the grace for that frame is 20 s here,
# VKBOOK_STOP_GRACE_MS below: a frame under synchronization validation on a loaded machine, or in
# the sanitizers' build, may take longer than the 0.4 s a reader gets).
[ $status = 0 ] || fail "the chapter exited with $status"
grep "^shaders: reloaded" "$work/stdout" | tail -1
if [ -n "${EXPECT_PIPELINES:-}" ]; then
    total=$(grep -cE "fault_injection: vkCreate(Graphics|Compute)Pipelines #" "$work/stderr")
    [ $((total - made)) = "$EXPECT_PIPELINES" ] ||
        fail "the reload made $((total - made)) pipelines ($total in all, $made at start-up), not $EXPECT_PIPELINES"
    echo "live_reload: the reload made $((total - made)) pipeline(s), as expected"
    grep -v "^VK_LAYER_VKBOOK_fault_injection: " "$work/stderr" > "$work/stderr.kept"
    mv "$work/stderr.kept" "$work/stderr"
    unset VKBOOK_FAULT_TRACE
fi

# With the object-names layer (tests/reliability/names.cmake): every object the run made, the reloads'
# pipelines included, has a name.
if [ -n "${VKBOOK_NAMES_REPORT:-}" ]; then
    [ -s "$VKBOOK_NAMES_REPORT" ] || fail "no names report (was the layer loaded?)"
    if grep -q '^unnamed ' "$VKBOOK_NAMES_REPORT"; then
        fail "objects without a name: $(grep '^unnamed ' "$VKBOOK_NAMES_REPORT" | sort | uniq -c | head -5)"
    fi
    echo "names: $(grep -c '^named pipeline ' "$VKBOOK_NAMES_REPORT") pipelines named"
fi

# What the last frame shows.
unset VKBOOK_FAULT VKBOOK_FAULT_LAYER VKBOOK_NAMES_LAYER  # the references are rendered without the layers
reference build "$work/original.png"
case $scenario in
edit | fix | fault | save-* | during-compile | accept)
    reference "$work/edited" "$work/edited.png"
    "$image_compare" "$work/last.png" --golden "$work/edited.png" --max-diff 2 --max-fraction 0.001 ||
        fail "the last frame is not the edited shader's"
    "$image_compare" "$work/last.png" --golden "$work/original.png" --max-diff 2 --max-fraction 0.001 \
        > /dev/null 2>&1 && fail "the last frame is the unedited shader's"
    ;;
broken | interface | rule)
    if [ $gui = 1 ]; then  # the overlay shows the error over the unedited image
        "$image_compare" "$work/last.png" --golden "$work/original.png" --max-diff 2 --max-fraction 0.001 \
            > /dev/null 2>&1 && fail "the overlay does not show the error"
    else
        "$image_compare" "$work/last.png" --golden "$work/original.png" --max-diff 2 --max-fraction 0.001 ||
            fail "the last frame is not the unedited shader's"
    fi
    ;;
esac
cat "$work/stderr" >&2
echo "live_reload: $scenario: ok"
