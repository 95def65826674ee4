#!/usr/bin/env bash
# The Windows build, made and tested on Linux: MinGW-w64 compiles real .exe files, Wine runs them,
# and Wine's winevulkan hands their Vulkan calls to this machine's driver (lavapipe).
#
#   scripts/windows-cross.sh deps    the packages (MinGW-w64, Wine), Debian's sources of the
#                                    libraries, and the Vulkan headers and import library for
#                                    MinGW, into build-windows-deps/ (kept between runs)
#   scripts/windows-cross.sh test    deps, then cmake --preset windows-cross, build, ctest -L windows
#
# Nothing is downloaded from outside Debian's archive: the libraries' sources are Debian's source
# packages (the same versions the Linux build uses), handed to CMake's FetchContent as local
# sources (CMakePresets.json sets FETCHCONTENT_SOURCE_DIR_*).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps=$root/build-windows-deps
sysroot=$deps/sysroot
sources=$deps/src
sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)

packages=(g++-mingw-w64-x86-64-posix mingw-w64-tools wine64 wine libwine dpkg-dev xvfb)
# Source package -> the name FetchContent knows it by (cmake/Dependencies.cmake).
declare -A source_packages=([glfw3]=glfw3 [glm]=glm [nlohmann-json3]=nlohmann_json
                            [tinyobjloader]=tinyobjloader [libstb]=stb [imgui]=imgui
                            [tinygltf]=tinygltf [cli11]=cli11)

install_packages() {
    local missing=()
    for p in "${packages[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "windows-cross: installing ${missing[*]}"
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# apt-get source needs deb-src entries. Where the machine has none, they are made from its own
# deb entries (the same archive and suites), so no archive address is written down anywhere here.
enable_deb_src() {
    if apt-get source --print-uris -qq glfw3 > /dev/null 2>&1; then return 0; fi
    echo "windows-cross: adding deb-src entries made from this machine's apt sources"
    local list=/etc/apt/sources.list.d/vkbook-deb-src
    local made=false
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        grep -Eq '^Types:(.* )?deb( |$)' "$f" || continue
        sed -E 's/^Types:.*/Types: deb-src/' "$f" | "${sudo[@]}" tee -a "$list.sources" > /dev/null
        echo | "${sudo[@]}" tee -a "$list.sources" > /dev/null
        made=true
    done
    if [ -f /etc/apt/sources.list ] && grep -q '^deb ' /etc/apt/sources.list; then
        sed -n 's/^deb /deb-src /p' /etc/apt/sources.list | "${sudo[@]}" tee "$list.list" > /dev/null
        made=true
    fi
    $made || { echo "windows-cross: no apt sources to make deb-src entries from" >&2; exit 1; }
    "${sudo[@]}" apt-get update -q
}

fetch_sources() {
    mkdir -p "$sources"
    for package in "${!source_packages[@]}"; do
        local name=${source_packages[$package]}
        [ -e "$sources/$name" ] && continue
        (cd "$sources" && apt-get source -qq "$package" > /dev/null 2>&1) ||
            { echo "windows-cross: apt-get source $package failed" >&2; exit 1; }
        # A stable name for the unpacked directory (e.g. glfw3-3.3.8 -> glfw3).
        local dir
        dir=$(find "$sources" -maxdepth 1 -type d -name "$package-*" | head -n 1)
        ln -sfn "$(basename "$dir")" "$sources/$name"
    done
}

# The Vulkan headers (copied: the MinGW compiler must not see the host's /usr/include) and an
# import library for vulkan-1.dll, made from Wine's own DLL, which forwards to winevulkan.
vulkan_for_mingw() {
    [ -f "$sysroot/lib/libvulkan-1.a" ] && return 0
    mkdir -p "$sysroot/include" "$sysroot/lib"
    cp -r /usr/include/vulkan /usr/include/vk_video "$sysroot/include/"
    local dll
    dll=$(find /usr/lib/x86_64-linux-gnu/wine /usr/lib/wine -path '*x86_64-windows*' -name vulkan-1.dll 2> /dev/null | head -n 1)
    [ -n "$dll" ] || { echo "windows-cross: Wine's vulkan-1.dll not found" >&2; exit 1; }
    gendef - "$dll" > "$deps/vulkan-1.def" 2> /dev/null
    x86_64-w64-mingw32-dlltool -d "$deps/vulkan-1.def" -D vulkan-1.dll -l "$sysroot/lib/libvulkan-1.a"
}

command=${1:-}
case "$command" in
    deps)
        install_packages
        enable_deb_src
        fetch_sources
        vulkan_for_mingw
        ;;
    test)
        "$0" deps
        cd "$root"
        started=$SECONDS
        cmake --preset windows-cross
        # The build runs its scene generators under Wine, several at once. Without a display no
        # Wine process stays up between them, so each may start a wineserver as the last one's is
        # exiting, and lose it ("wine client error: recvmsg: Connection reset by peer"). One
        # persistent wineserver for the whole build (ended after it; the tests keep theirs up with
        # a display, tests/desktops/wine_display.sh) leaves nothing to race with.
        prefix=$root/build-windows/wine-prefix
        VKBOOK_WINEPREFIX=$prefix "$root/cmake/toolchains/wine-run.sh" cmd.exe /c exit  # makes the prefix
        WINEPREFIX=$prefix wineserver -w
        WINEPREFIX=$prefix wineserver -p
        trap 'WINEPREFIX=$prefix wineserver -k 2> /dev/null || true' EXIT
        cmake --build --preset windows-cross -j "$(nproc)"
        WINEPREFIX=$prefix wineserver -k 2> /dev/null || true
        echo "windows-cross: build took $((SECONDS - started)) s"
        started=$SECONDS
        ctest --preset windows-cross -j "$(($(nproc) + 1))" --output-junit "$root/build-windows/ctest-junit.xml"
        echo "windows-cross: test stage took $((SECONDS - started)) s"
        ;;
    *)
        echo "usage: scripts/windows-cross.sh deps | test" >&2
        exit 2
        ;;
esac
