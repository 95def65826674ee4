#!/usr/bin/env bash
# A run killed between writing its new pipeline cache and renaming it over the old one, as a crash
# would kill it (a power cut could also lose what the kernel had not written yet: we do not fsync): gdb stops the chapter at rename() (common/vk/pipeline.cpp,
# savePipelineCache) and kills it there. The old cache must be untouched (the same bytes), and the
# next run must load it with nothing on stderr, remove the dead run's temporary and leave none of
# its own.
#
#   cache_crash.sh CHAPTER [options...]
set -u
chapter=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME=$work/cache
fail() {
    echo "cache_crash: $*"
    exit 1
}
"$chapter" "$@" > /dev/null 2> "$work/err" || fail "first run failed: $(cat "$work/err")"
cache=$(ls "$XDG_CACHE_HOME"/vulkan-book-cpp/*.bin 2> /dev/null | head -1)
[ -n "$cache" ] || fail "the first run wrote no cache"
before=$(md5sum < "$cache")
# Only our rename: Mesa's own shader cache, which renames files too, is off for this run.
MESA_SHADER_CACHE_DISABLE=true gdb -batch -nx -ex 'set breakpoint pending on' -ex 'break rename' -ex run -ex bt -ex kill \
    --args "$chapter" "$@" > "$work/gdb.txt" 2>&1
grep -q "hit Breakpoint 1.*rename" "$work/gdb.txt" || fail "the run did not stop at rename(): $(tail -5 "$work/gdb.txt")"
grep -q "savePipelineCache" "$work/gdb.txt" || fail "stopped at another rename(): $(grep -A8 'hit Breakpoint' "$work/gdb.txt")"
temporary=$(ls "$XDG_CACHE_HOME"/vulkan-book-cpp/*.tmp* 2> /dev/null | head -1)
[ -n "$temporary" ] || fail "no temporary file: the run was not killed between the write and the rename"
[ "$(md5sum < "$cache")" = "$before" ] || fail "the cache changed although the run died before its rename"
echo "cache_crash: killed at rename(); the old cache is whole, $(basename "$temporary") left behind"
leftover=$(basename "$temporary")
"$chapter" "$@" > /dev/null 2> "$work/err" || fail "the next run failed: $(cat "$work/err")"
[ -s "$work/err" ] && fail "the next run printed: $(cat "$work/err")"
# The killed run's temporary is removed by the next run that saves (its process is gone:
# common/core/files.cpp, removeStaleTemporaries), and that run leaves none of its own.
for file in "$XDG_CACHE_HOME"/vulkan-book-cpp/*.tmp*; do
    [ -e "$file" ] || continue  # no match: the pattern itself
    fail "the next run left $(basename "$file") behind"
done
echo "cache_crash: the next run loads the old cache with nothing on stderr and removes $leftover"
