#!/usr/bin/env bash
# docs.options and docs.file-lines: what in the docs can be checked against the code mechanically.
#
#   tests/docs/docs_check.sh options ROOT PROGRAM...   every option a program's --help lists is in one of
#                                                 the README's option tables marked as that
#                                                 program's (<!-- options-for: ... -->), and every
#                                                 program a table is marked for has each of its
#                                                 options
#   tests/docs/docs_check.sh file-lines ROOT           every FILE:LINE a page quotes (docs/*.md, the
#                                                 READMEs) names a file of the repository that has
#                                                 that line
#   tests/docs/docs_check.sh counts ROOT BUILD         every count of tests a page marks, as
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
        # that cell counts (`--width W`, `--height H`). Each table follows a line
        # "<!-- options-for: PROGRAM... -->" naming the programs that take all of its options.
        # Out: "LINE PROGRAM OPTION" for every program of a table and every option of its rows.
        rows=$(awk '
            /^<!-- options-for: .* -->$/ { sub(/^<!-- options-for: /, ""); sub(/ -->$/, ""); programs = $0; next }
            /^\| `--/ {
                if (programs == "") { print NR " - -"; next }
                split($0, cells, "|"); cell = cells[2]; n = split(programs, names, " ")
                while (match(cell, /--[a-z][a-z0-9-]*/)) {
                    for (i = 1; i <= n; i++) print NR " " names[i] " " substr(cell, RSTART, RLENGTH)
                    cell = substr(cell, RSTART + RLENGTH)
                }
                next
            }
        ' "$root/README.md")
        [ -n "$rows" ] || problem "README.md: no option table (rows starting with | \`--)"
        while read -r line name _; do
            [ "$name" = - ] && problem "README.md:$line: an option row with no <!-- options-for: ... --> line before its table"
        done <<<"$rows"
        for program in "$@"; do
            name=$(basename "$program" .exe)
            help=$("$program" --help) || { problem "$program --help failed"; continue; }
            # The options --help describes: lines that start (indented) with --name.
            offered=$(grep -oE -- '^ +--[a-z][a-z0-9-]*' <<<"$help" | tr -d ' ' | sort -u || true)
            [ -n "$offered" ] || problem "$name --help lists no option"
            documented=$(awk -v p="$name" '$2 == p { print $3 }' <<<"$rows" | sort -u)
            for option in $offered; do
                grep -qxF -- "$option" <<<"$documented" ||
                    problem "README.md: $name offers $option, which no option table for $name lists"
            done
            while read -r line option; do
                [ -n "$option" ] || continue
                grep -qxF -- "$option" <<<"$offered" ||
                    problem "README.md:$line: the table says $name takes $option; its --help has no such option"
            done < <(awk -v p="$name" '$2 == p { print $1, $3 }' <<<"$rows")
        done
        # Every program a table names is one of those checked.
        for listed in $(awk '$2 != "-" { print $2 }' <<<"$rows" | sort -u); do
            found=0
            for program in "$@"; do [ "$(basename "$program" .exe)" = "$listed" ] && found=1; done
            [ $found = 1 ] || problem "README.md: an option table names $listed, which is not among the programs checked"
        done
        ;;
    file-lines)
        pages=("$root"/docs/*.md "$root/README.md" "$root/tests/data/README.md")
        while IFS=: read -r page _ ref; do
            file=${ref%:*}
            line=${ref##*:}
            # An absolute path is a reader's machine's (a compiler message quoted), not ours.
            [[ $file == /* ]] && continue
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
