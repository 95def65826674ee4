#!/usr/bin/env bash
# docs.options and docs.file-lines: what in the docs can be checked against the code mechanically.
#
#   tests/docs_check.sh options ROOT PROGRAM...   every option a program's --help lists is in one of
#                                                 the README's option tables, and every option a
#                                                 table lists is one some program's --help has
#   tests/docs_check.sh file-lines ROOT           every FILE:LINE a page quotes (docs/*.md, the
#                                                 READMEs) names a file of the repository that has
#                                                 that line
#   tests/docs_check.sh counts ROOT BUILD         every count of tests a page marks, as
#                                                 "N tests<!-- ctest: REGEX -->", is what
#                                                 `ctest -N -R REGEX` counts in BUILD
#
# Prints each problem on a line of its own and exits 1 when there is one.
set -euo pipefail
mode=${1:-}
root=${2:-}
[ -n "$mode" ] && [ -d "$root" ] || { echo "usage: docs_check.sh options|file-lines|counts ROOT [...]" >&2; exit 2; }
shift 2
root=$(cd "$root" && pwd)
problems=0
problem() {
    echo "$1"
    problems=$((problems + 1))
}

case $mode in
    options)
        # The README's option tables: rows whose first cell starts with `--...`; every --name in
        # that cell counts (`--width W`, `--height H`).
        documented=$(grep -E '^\| `--' "$root/README.md" | cut -d'|' -f2 | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u || true)
        [ -n "$documented" ] || problem "README.md: no option table (rows starting with | \`--)"
        offered=""
        for program in "$@"; do
            help=$("$program" --help) || { problem "$program --help failed"; continue; }
            # The options --help describes: lines that start (indented) with --name.
            names=$(grep -oE -- '^ +--[a-z][a-z0-9-]*' <<<"$help" | tr -d ' ' | sort -u || true)
            [ -n "$names" ] || problem "$(basename "$program") --help lists no option"
            offered+=$'\n'$names
            for name in $names; do
                grep -qxF -- "$name" <<<"$documented" ||
                    problem "README.md: $(basename "$program") offers $name, which no option table lists"
            done
        done
        offered=$(sort -u <<<"$offered")
        for name in $documented; do
            grep -qxF -- "$name" <<<"$offered" ||
                problem "README.md: an option table lists $name, which no program's --help offers"
        done
        ;;
    file-lines)
        pages=("$root"/docs/*.md "$root/README.md" "$root/tests/data/README.md")
        while IFS=: read -r page _ ref; do
            file=${ref%:*}
            line=${ref##*:}
            # A bare name (main.cpp:12) or a path from the root (chapter-15/main.cpp:12).
            if [ -f "$root/$file" ]; then
                matches=("$root/$file")
            else
                mapfile -t matches < <(find "$root" -type d \( -name 'build*' -o -name '.*' \) -prune -o -type f \
                                           -name "$(basename "$file")" -print | grep -F -- "/$file")
            fi
            if [ ${#matches[@]} -ne 1 ]; then
                problem "${page#"$root"/}: $ref: ${#matches[@]} files of that name (give the path from the root)"
                continue
            fi
            lines=$(wc -l < "${matches[0]}")
            [ "$line" -ge 1 ] && [ "$line" -le "$lines" ] ||
                problem "${page#"$root"/}: $ref: the file has $lines lines"
        done < <(grep -oE '[A-Za-z0-9_./-]+\.(cpp|hpp|h|glsl|frag|vert|comp|cmake|sh|json):[0-9]+' "${pages[@]}" |
                 sed -E 's/^([^:]+):/\1::/')
        ;;
    counts)
        build=${1:?the build directory}
        pages=("$root"/docs/*.md "$root/README.md")
        # "N<anything but a digit or '<', at most 60 characters><!-- ctest: REGEX -->"
        while IFS= read -r hit; do
            page=${hit%%:*}
            rest=${hit#*:}
            quoted=$(grep -oE '^[0-9][0-9,]*' <<<"$rest" | tr -d ,)
            regex=$(sed -E 's/.*<!-- ctest: (.*) -->$/\1/' <<<"$rest")
            counted=$(ctest --test-dir "$build" -N -R "$regex" | sed -n 's/^Total Tests: //p' || true)
            [ "$quoted" = "$counted" ] ||
                problem "${page#"$root"/}: says $quoted tests where \`ctest -N -R '$regex'\` counts ${counted:-none}"
        done < <(grep -oE '[0-9][0-9,]*[^0-9<]{0,60}<!-- ctest: [^>]* -->' "${pages[@]}")
        ;;
    *)
        echo "docs_check.sh: unknown mode '$mode'" >&2
        exit 2
        ;;
esac
[ "$problems" -eq 0 ] || { echo "$problems problem(s)"; exit 1; }
echo "docs_check.sh $mode: no problem"
