#!/usr/bin/env bash
# Runs a command on an Xvfb display of its own, as `xvfb-run -a` does, but without its races when
# many windowed tests run at once: Xvfb picks a free display number itself and writes it to a file
# descriptor once it accepts connections (-displayfd), and there is no authorization file to
# clean up (xvfb-run's cleanup failed now and then with "problem while cleaning up temporary
# directory", exit 5, under ctest -j). Only local connections are possible (-nolisten tcp).
#   xvfb_run.sh [-a] [-s "SERVER ARGS"] COMMAND [ARGS...]     (-a is accepted and implied)
set -u
server_args="-screen 0 1280x1024x24"
while [ $# -gt 0 ]; do
    case $1 in
        -a) shift ;;
        -s) server_args=$2; shift 2 ;;
        *) break ;;
    esac
done
dir=$(mktemp -d "${TMPDIR:-/tmp}/xvfb_run.XXXXXX")
# shellcheck disable=SC2086  # the server arguments are words
Xvfb -displayfd 3 -nolisten tcp $server_args 3> "$dir/display" 2> "$dir/log" &
xvfb=$!
for _ in $(seq 1 200); do
    [ -s "$dir/display" ] && break
    if ! kill -0 "$xvfb" 2> /dev/null; then
        echo "xvfb_run: Xvfb did not start:" >&2
        cat "$dir/log" >&2
        rm -rf "$dir"
        exit 1
    fi
    sleep 0.05
done
display=$(head -n 1 "$dir/display")
if [ -z "$display" ]; then
    echo "xvfb_run: Xvfb gave no display number within 10 s" >&2
    kill "$xvfb" 2> /dev/null
    rm -rf "$dir"
    exit 1
fi
DISPLAY=":$display" "$@"
rc=$?
kill "$xvfb" 2> /dev/null
wait "$xvfb" 2> /dev/null
rm -rf "$dir"
exit "$rc"
