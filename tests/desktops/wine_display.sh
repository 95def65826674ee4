#!/usr/bin/env bash
# The X display and the Wine prefix the Windows tests share (tests/desktops/windows.cmake):
#   wine_display.sh start BUILD_DIR   an Xvfb display of its own (-displayfd: a free number, no
#                                     races), recorded in BUILD_DIR/wine-prefix.display, where
#                                     cmake/toolchains/wine-run.sh finds it; and the prefix made
#   wine_display.sh stop BUILD_DIR    Wine's processes and the Xvfb ended, the record removed
set -u
command=$1
build=$2
prefix=$build/wine-prefix
record=$prefix.display
case $command in
    start)
        "$0" stop "$build" 2> /dev/null
        log=$(mktemp "${TMPDIR:-/tmp}/wine_display.XXXXXX")
        # setsid: the server outlives this script (and is ended by `stop`).
        setsid Xvfb -displayfd 3 -nolisten tcp -screen 0 1600x1200x24 < /dev/null > /dev/null 3> "$log.display" 2> "$log" &
        xvfb=$!
        for _ in $(seq 1 200); do
            [ -s "$log.display" ] && break
            kill -0 "$xvfb" 2> /dev/null || { echo "wine_display: Xvfb did not start:" >&2; cat "$log" >&2; exit 1; }
            sleep 0.05
        done
        [ -s "$log.display" ] || { echo "wine_display: Xvfb gave no display number" >&2; exit 1; }
        mkdir -p "$(dirname "$record")"
        { head -n 1 "$log.display"; echo "$xvfb"; } > "$record"
        rm -f "$log" "$log.display"
        # The prefix, made now rather than by the first of several tests started at once.
        "$(dirname "$0")/../../cmake/toolchains/wine-run.sh" "$build/bin/$(ls "$build/bin" | grep -m1 '\.exe$')" --help < /dev/null > /dev/null 2>&1
        ;;
    stop)
        [ -f "$record" ] || exit 0
        WINEPREFIX=$prefix wineserver -k 2> /dev/null
        kill "$(sed -n 2p "$record")" 2> /dev/null
        rm -f "$record"
        ;;
    *)
        echo "usage: wine_display.sh start|stop BUILD_DIR" >&2
        exit 2
        ;;
esac
