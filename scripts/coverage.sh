#!/usr/bin/env bash
# What the sanitizer stage's selection covers against the whole Release suite: line coverage
# (gcov, reported by gcovr) of common/ and the chapters' sources.
#
#   scripts/coverage.sh            build build-coverage/ (Release at -O1, --coverage), then
#                                  1. run the sanitizer stage's selection (tests/reliability/sanitizer/
#                                     selection.sh) and take its coverage;
#                                  2. run the rest of the suite and take the whole suite's coverage;
#                                  and print both, the ratio, and the lines only the rest covers.
#   scripts/coverage.sh --selection-again
#                                  step 1 only, against the whole suite's coverage of the last full
#                                  run (for a changed selection; the code must be the same).
#
# The standalone builds, the fuzzers and the Windows build compile programs of their own, not
# these instrumented ones: they are left out of both runs (they add no line to either). Needs
# gcovr (Debian package gcovr). Writes build-coverage/coverage-{selection,suite}.json and .txt.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-coverage
source "$root/tests/reliability/sanitizer/selection.sh"
command -v gcovr > /dev/null || { echo "coverage: gcovr is not installed (apt-get install gcovr)" >&2; exit 2; }
not_instrumented='standalone|^fuzz\.|^windows\.'

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS=--coverage -DCMAKE_EXE_LINKER_FLAGS=--coverage > /dev/null
cmake --build "$build" -j "$(nproc)"
jobs=$(($(nproc) + 1))

# gcovr over our sources only: common/ and every chapter directory (not tests/, not the
# libraries' headers).
report() {  # report NAME
    (cd "$build" && gcovr --root "$root" --filter "$root/common/" --filter "$root/chapter-" \
        --exclude-unreachable-branches --json "$build/coverage-$1.json" --txt "$build/coverage-$1.txt" \
        --gcov-ignore-parse-errors --print-summary "$build" > /dev/null)
    tail -n 3 "$build/coverage-$1.txt"
}
lines() {  # lines JSON: "covered total" over every file, and the covered lines as file:line
    python3 - "$1" "$2" << 'PY'
import json, sys
data = json.load(open(sys.argv[1]))
covered, total, keys = 0, 0, []
for f in data['files']:
    for line in f['lines']:
        if line.get('gcovr/noncode'):
            continue
        total += 1
        if line['count'] > 0:
            covered += 1
            keys.append(f"{f['file']}:{line['line_number']}")
open(sys.argv[2], 'w').write('\n'.join(sorted(keys)) + '\n')
print(covered, total)
PY
}

again=0
[ "${1:-}" = --selection-again ] && again=1
if [ $again = 1 ] && [ ! -f "$build/coverage-suite.json" ]; then
    echo "coverage: no whole-suite coverage in $build to compare with: run scripts/coverage.sh first" >&2
    exit 2
fi
find "$build" -name '*.gcda' -delete
set +e
ctest --test-dir "$build" -j "$jobs" -E "$sanitize_skip|$not_instrumented" --output-junit "$build/junit-selection.xml" \
    > "$build/ctest-selection.log" 2>&1
echo "coverage: the sanitizer stage's selection ran ($(grep -c ' Passed ' "$build/ctest-selection.log") passed): $(tail -n 1 "$build/ctest-selection.log")"
report selection > /dev/null
[ $again = 1 ] || ctest --test-dir "$build" -j "$jobs" -R "$sanitize_skip" -E "$not_instrumented" --output-junit "$build/junit-rest.xml" \
    > "$build/ctest-rest.log" 2>&1
if [ $again = 0 ]; then
    echo "coverage: the rest of the suite ran ($(grep -c ' Passed ' "$build/ctest-rest.log") passed): $(tail -n 1 "$build/ctest-rest.log")"
    report suite > /dev/null
fi
set -e
read -r sel_covered sel_total < <(lines "$build/coverage-selection.json" "$build/lines-selection.txt")
read -r all_covered all_total < <(lines "$build/coverage-suite.json" "$build/lines-suite.txt")
awk -v s="$sel_covered" -v a="$all_covered" -v t="$all_total" 'BEGIN {
    printf "coverage: whole suite %d of %d lines (%.2f%%); sanitizer selection %d (%.2f%%): %.2f%% of the suite'"'"'s\n",
           a, t, 100 * a / t, s, 100 * s / t, 100 * s / a }'
echo "coverage: lines only the rest of the suite covers, by file:"
comm -13 "$build/lines-selection.txt" "$build/lines-suite.txt" | sed 's/:[0-9]*$//' | sort | uniq -c | sort -rn | head -20
