#!/usr/bin/env bash
# One command from a fresh Debian/Ubuntu machine to a running chapter or a green test suite.
#
#   scripts/setup.sh run [chapter-NN] [options...]   install, build (Release), run a chapter
#   scripts/setup.sh test                            install, build (Release), run every test;
#                                                    then build with the sanitizers and run the
#                                                    headless tests again (docs/reliability.md);
#                                                    then build the Windows .exe files with
#                                                    MinGW-w64 and test them under Wine
#                                                    (scripts/windows-cross.sh)
#
# Installs only the Debian packages that are missing (with sudo when not root), configures
# build/ in Release and builds it. `run` opens a window when a display is available, otherwise
# renders headless to build/<chapter>.png and says so.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build"
default_chapter=chapter-15

packages=(
    build-essential cmake pkg-config            # compiler and build
    libvulkan-dev mesa-vulkan-drivers           # Vulkan loader + headers, lavapipe (CPU device)
    vulkan-validationlayers glslang-tools       # --validation, shader compiler
    libglfw3-dev libglm-dev libstb-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libgtest-dev
    libimgui-dev libcli11-dev
    libshaderc-dev glslang-dev libspirv-cross-c-shared-dev   # shaders compiled at run time, live reload
    xvfb xauth xdotool jwm clang-format         # tests: windowed runs, key presses, minimising, formatting
    clang-14 libclang-rt-14-dev llvm-14         # tests: libFuzzer targets (tests/reliability/fuzz/), symbolized reports
    gdb python3                                 # tests: a run killed mid-save (tests/reliability/cache_crash.sh), docs checks
    libembree-dev                               # tests: the shadow study's reference (rays through a BVH)
    libgl1 libegl1 libopengl0                   # scripts/gpu_package.sh: GLVND, which NVIDIA's driver loads
)

install_missing() {
    local missing=()
    for p in "${packages[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "setup: installing ${missing[*]}"
    local sudo=()
    [ "$(id -u)" -eq 0 ] || sudo=(sudo)
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

build_release() {
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
    cmake --build "$build" -j "$(nproc)"
}

# AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer, optimised with debug info.
sanitize_build="$root/build-sanitize"
build_sanitize() {
    cmake -S "$root" -B "$sanitize_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVKBOOK_SANITIZE=ON
    cmake --build "$sanitize_build" -j "$(nproc)"
}
# Not run again under the sanitizers: the window-life tests, desktop.present-fences-window-life
# among them, and the live-reload leak tests (they measure resident memory, which
# AddressSanitizer's shadow memory and quarantine inflate), chapter-15.window-keys (it checks how
# far keys held for 0.7 s of wall-clock time move the lights, and the sanitizer build's slower
# frames sample the key presses too coarsely: seen once, 2.83 instead of >= 3), builds of a
# chapter on its own, formatting, docs, the fuzzers (built with sanitizers of their own), and the
# GPU package's list (it maps the Release binaries' libraries; these would add the sanitizers'),
# and the peak memory of the largest admitted models (AddressSanitizer's shadow memory inflates it),
# and chapter-16.reload-walk (two minutes of walking and reloading in the Release build, past its
# five-minute limit under the sanitizers; chapter-16's reloads run there in live-reload.chapter-16.*).
sanitize_skip='window-life|^extremes\.memory-|^chapter-15\.window-keys$|standalone|^format$|^docs\.|^fuzz\.|^live-reload\..*\.leak$|^scripts\.|^chapter-16\.reload-walk$'

command=${1:-}
[ $# -gt 0 ] && shift
case "$command" in
    run)
        chapter=$default_chapter
        if [ $# -gt 0 ] && [[ $1 == chapter-* ]]; then chapter=$1; shift; fi
        install_missing
        build_release
        if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
            echo "setup: running $chapter in a window (Escape closes it)"
            exec "$build/bin/$chapter" "$@"
        fi
        echo "setup: no display, running $chapter headless"
        "$build/bin/$chapter" --headless --screenshot "$build/$chapter.png" "$@"
        echo "setup: wrote $build/$chapter.png"
        ;;
    test)
        install_missing
        build_release
        # The fuzz targets are test programs like the others: built here, not in the test stage
        # (their own clang tree; the target exists where clang can link them).
        # (grep reads the whole list: -q would stop early and fail the pipe under pipefail)
        if cmake --build "$build" --target help | grep 'fuzz-targets' > /dev/null; then
            started=$SECONDS
            cmake --build "$build" --target fuzz-targets
            echo "setup: fuzz targets built in $((SECONDS - started)) s"
        fi
        # One test more than there are cores: the windowed tests spend much of their time waiting
        # (window manager, xdotool, sleeps), and the cores stay busy meanwhile.
        jobs=$(($(nproc) + 1))
        started=$SECONDS
        ctest --test-dir "$build" --output-on-failure -j "$jobs"
        echo "setup: test stage took $((SECONDS - started)) s"
        build_sanitize
        started=$SECONDS
        ctest --test-dir "$sanitize_build" --output-on-failure -j "$jobs" -E "$sanitize_skip"
        echo "setup: sanitizer test stage took $((SECONDS - started)) s"
        started=$SECONDS
        "$root/scripts/windows-cross.sh" test
        echo "setup: Windows stage (packages, sources, build, tests under Wine) took $((SECONDS - started)) s"
        ;;
    *)
        echo "usage: scripts/setup.sh run [chapter-NN] [options...] | scripts/setup.sh test" >&2
        exit 2
        ;;
esac
