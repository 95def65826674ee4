#!/usr/bin/env bash
# Shaders compiled when a chapter starts (the book's ShaderCompiler rule: a source newer than the
# build's SPIR-V is compiled and used), and what happens without sources.
#
#   runtime_shaders.sh SCENARIO SHADERS IMAGE_COMPARE CHAPTER [options...]
#
#   newer       a copy of the sources with the fragment colour of FILE (env, e.g.
#               chapter-06/triangle.frag) replaced: the chapter says it compiled it, and its image
#               differs from the build's SPIR-V's where the edit says (magenta where red was);
#   error       a copy with a syntax error at a known line of FILE: exit code 2 and one line
#               "FILE:LINE: error: ..." on stderr, nothing rendered;
#   interface   a copy whose FILE reads a descriptor (set 6) the pipeline layout does not have:
#               exit code 2 and one line "FILE: interface changed: ..." on stderr;
#   constant-id a copy whose FILE moves a specialization constant to another constant_id (SED):
#               exit code 1 and one line naming the shader and the ID the pipeline still sets;
#   no-sources  the executable and its shaders/ copied elsewhere with the recorded source
#               directory gone (a copied bin/): --help says the build's SPIR-V is used and why,
#               and the image is the build's.
set -u
scenario=$1 shaders=$2 image_compare=$3 chapter=$4
shift 4
work=$(mktemp -d "${TMPDIR:-/tmp}/runtime_shaders.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
    echo "runtime_shaders: $*"
    exit 1
}
"$chapter" "$@" --headless --screenshot "$work/build.png" > /dev/null || fail "the build's run failed"

case $scenario in
newer)
    cp -r "$shaders" "$work/shaders"
    sed -i 's/vec3(1.0, 0.0, 0.0)/vec3(1.0, 0.0, 1.0)/' "$work/shaders/$FILE"
    grep -q "vec3(1.0, 0.0, 1.0)" "$work/shaders/$FILE" || fail "the edit did not apply to $FILE"
    # The build's SPIR-V stays the build's: the program compiles in memory and writes no .spv.
    spirv=$(cd "$(dirname "$chapter")/shaders" && find . -name '*.spv' -exec md5sum {} + | sort)
    "$chapter" "$@" --headless --shader-dir "$work/shaders" --screenshot "$work/edited.png" > "$work/stdout" ||
        fail "the run with the edited source failed"
    [ "$(cd "$(dirname "$chapter")/shaders" && find . -name '*.spv' -exec md5sum {} + | sort)" = "$spirv" ] ||
        fail "the run changed the build's .spv files"
    [ -z "$(find "$work/shaders" -name '*.spv')" ] || fail "the run wrote .spv files beside the sources"
    grep -q "^shaders: compiled $FILE (its source is newer than the build's SPIR-V)" "$work/stdout" ||
        fail "no 'compiled $FILE' line: $(cat "$work/stdout")"
    "$image_compare" "$work/edited.png" $PIXELS || fail "the edit is not in the image"
    "$image_compare" "$work/build.png" $PIXELS > /dev/null 2>&1 && fail "the build's image has the edit too"
    ;;
error)
    cp -r "$shaders" "$work/shaders"
    line=$(python3 - "$work/shaders/$FILE" << 'EOF'
import sys
path = sys.argv[1]
text = open(path).read()
end = text.rindex('}')
start = text.rindex('\n', 0, end) + 1
open(path, 'w').write(text[:start] + '    this is not GLSL;\n' + text[start:])
print(text[:start].count('\n') + 1)
EOF
)
    "$chapter" "$@" --headless --shader-dir "$work/shaders" --screenshot "$work/error.png" > /dev/null 2> "$work/stderr"
    status=$?
    [ $status = 2 ] || fail "exit code $status, expected 2"
    [ "$(wc -l < "$work/stderr")" = 1 ] || fail "not one line on stderr: $(cat "$work/stderr")"
    grep -q "$FILE:$line: error: " "$work/stderr" || fail "the error does not name $FILE:$line: $(cat "$work/stderr")"
    [ -e "$work/error.png" ] && fail "an image was written"
    cat "$work/stderr"
    ;;
interface)
    cp -r "$shaders" "$work/shaders"
    python3 - "$work/shaders/$FILE" << 'EOF'
import sys
path = sys.argv[1]
text = open(path).read()
end = text.rindex('}')
start = text.rindex('\n', 0, end) + 1
text = text[:start] + '    outColor = extraInput.color;\n' + text[start:]
at = text.index('layout(location = 0) out vec4 outColor;')
declaration = 'layout(set = 6, binding = 0) uniform ExtraInput { vec4 color; } extraInput;\n'
open(path, 'w').write(text[:at] + declaration + text[at:])
EOF
    "$chapter" "$@" --headless --shader-dir "$work/shaders" > /dev/null 2> "$work/stderr"
    status=$?
    [ $status = 2 ] || fail "exit code $status, expected 2"
    [ "$(wc -l < "$work/stderr")" = 1 ] || fail "not one line on stderr: $(cat "$work/stderr")"
    grep -q "$FILE: interface changed: it uses set 6 binding 0 (uniform block ExtraInput)" "$work/stderr" ||
        fail "not refused as an interface change: $(cat "$work/stderr")"
    cat "$work/stderr"
    ;;
newer-include)
    # Sources copied with their times (older than the build's SPIR-V), then one included file
    # (INCLUDE) made newer: the shaders that include it (COMPILED, space-separated) are compiled,
    # and no other.
    cp -rp "$shaders" "$work/shaders"
    touch "$work/shaders/$INCLUDE"
    "$chapter" "$@" --headless --shader-dir "$work/shaders" --frames 1 > "$work/stdout" ||
        fail "the run failed"
    for file in $COMPILED; do
        grep -q "^shaders: compiled $file (its source is newer than the build's SPIR-V)" "$work/stdout" ||
            fail "$file, which includes $INCLUDE, was not compiled: $(grep '^shaders:' "$work/stdout")"
    done
    count=$(grep -c "^shaders: compiled .* (its source is newer" "$work/stdout")
    [ "$count" = "$(wc -w <<< "$COMPILED")" ] ||
        fail "$count shaders compiled, not only those that include $INCLUDE: $(grep '(its source is newer' "$work/stdout")"
    grep "^shaders: compiled .* (its source is newer" "$work/stdout"
    ;;
constant-id)
    # A learner's edit that moves a specialization constant to another constant_id (SED, a sed
    # expression, applied to FILE): the pipeline still sets the old ID, which the shader no longer
    # declares -- Vulkan would ignore it and leave the constant at its default. The chapter stops
    # with exit code 1 and one line naming the shader and the ID (EXPECT, a grep pattern).
    cp -r "$shaders" "$work/shaders"
    before=$(md5sum < "$work/shaders/$FILE")
    sed -i "$SED" "$work/shaders/$FILE"
    [ "$(md5sum < "$work/shaders/$FILE")" != "$before" ] || fail "the edit did not apply to $FILE"
    "$chapter" "$@" --headless --shader-dir "$work/shaders" --frames 1 > /dev/null 2> "$work/stderr"
    status=$?
    [ $status = 1 ] || fail "exit code $status, expected 1"
    [ "$(wc -l < "$work/stderr")" = 1 ] || fail "not one line on stderr: $(cat "$work/stderr")"
    grep -q "$EXPECT" "$work/stderr" || fail "not the message expected: $(cat "$work/stderr")"
    cat "$work/stderr"
    ;;
bad-output)
    # --check-output on a light output with a bad value (VALUE: a GLSL float written to every
    # pixel by the light shader FILE): exit 1 and one line.
    cp -r "$shaders" "$work/shaders"
    python3 - "$work/shaders/$FILE" "$VALUE" << 'EOF'
import sys
path = sys.argv[1]
text = open(path).read()
end = text.rindex('}')
start = text.rindex('\n', 0, end) + 1
open(path, 'w').write(text[:start] + '    outColor = vec4(vec3(%s), 1.0);\n' % sys.argv[2] + text[start:])
EOF
    "$chapter" "$@" --headless --shader-dir "$work/shaders" --check-output --frames 2 > "$work/stdout" 2> "$work/stderr"
    status=$?
    [ $status = 1 ] || fail "exit code $status, expected 1"
    [ "$(wc -l < "$work/stderr")" = 1 ] || fail "not one line on stderr: $(cat "$work/stderr")"
    grep -q "the light output has NaN, infinite or negative values" "$work/stderr" || fail "$(cat "$work/stderr")"
    grep "^light output" "$work/stdout"
    ;;
no-sources)
    mkdir -p "$work/bin"
    cp "$chapter" "$work/bin/"
    cp -r "$(dirname "$chapter")/shaders" "$work/bin/shaders"
    echo "$work/moved-away" > "$work/bin/shaders/source-dir.txt"
    copy="$work/bin/$(basename "$chapter")"
    "$copy" --help > "$work/help" || fail "--help failed"
    grep -q "^shaders: the build's SPIR-V (the build's sources ($work/moved-away) are not there)" "$work/help" ||
        fail "--help does not say the build's SPIR-V is used: $(grep shaders: "$work/help")"
    "$copy" "$@" --headless --screenshot "$work/copy.png" > /dev/null || fail "the copied program failed"
    "$image_compare" "$work/copy.png" --golden "$work/build.png" --max-diff 0 --max-fraction 0 ||
        fail "the copied program's image differs"
    grep "^shaders:" "$work/help"
    ;;
*) fail "unknown scenario '$scenario'" ;;
esac
echo "runtime_shaders: $scenario: ok"
