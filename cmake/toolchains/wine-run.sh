#!/bin/sh
# The cross build's emulator: runs a Windows executable under 64-bit Wine (Debian's wine64).
#   wine-run.sh PROGRAM.exe [ARGS...]
# The Wine prefix is $VKBOOK_WINEPREFIX, or wine-prefix/ in the current build tree (found from
# the program's path: <build>/bin/x.exe, <build>/tools/x.exe, <build>/tests/bin/x.exe), created
# on first use.
set -e
program=$1
if [ -z "${VKBOOK_WINEPREFIX:-}" ]; then
    dir=$(cd "$(dirname "$program")" && pwd)
    while [ "$dir" != / ] && [ ! -f "$dir/CMakeCache.txt" ]; do dir=$(dirname "$dir"); done
    [ -f "$dir/CMakeCache.txt" ] || { echo "wine-run.sh: no build tree above $program" >&2; exit 1; }
    VKBOOK_WINEPREFIX=$dir/wine-prefix
fi
WINEPREFIX=$VKBOOK_WINEPREFIX
# The X display the Windows tests share (tests/desktops/wine_display.sh starts it): Wine's Vulkan needs
# one even to render headless, and one display for all keeps Wine's desktop process on a server
# that outlives every test.
if [ -f "$WINEPREFIX.display" ]; then
    DISPLAY=:$(head -n 1 "$WINEPREFIX.display")
    export DISPLAY
fi
# -all: no Wine diagnostics on the program's stderr (the tests read it). No Mono or Gecko
# installers, no desktop menu entries in the user's home.
WINEDEBUG=${WINEDEBUG:--all}
WINEDLLOVERRIDES="mscoree,mshtml=;winemenubuilder.exe=d"
export WINEPREFIX WINEDEBUG WINEDLLOVERRIDES
# wine64 itself: /usr/bin/wine prints a "wine32 is missing" hint on stderr.
wine=/usr/lib/wine/wine64
[ -x "$wine" ] || wine=$(command -v wine64 || command -v wine)
if [ ! -f "$WINEPREFIX/.ready" ]; then
    mkdir -p "$WINEPREFIX"
    (
        flock 9  # tests run in parallel: one of them creates the prefix, the others wait
        if [ ! -f "$WINEPREFIX/.ready" ]; then
            "$wine" wineboot.exe -i > /dev/null 2>&1
            # Unmanaged windows: without a window manager (Xvfb), destroying a window otherwise
            # waits 2 s for a window-manager reply that never comes.
            "$wine" reg.exe add 'HKCU\Software\Wine\X11 Driver' /v Managed /d N /f > /dev/null 2>&1
            wineserver -w
            touch "$WINEPREFIX/.ready"
        fi
    ) 9> "$WINEPREFIX.lock"
fi
exec "$wine" "$@"
