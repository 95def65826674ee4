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
    ccache                                      # tests: the standalone builds share one compiler cache
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

# AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer, optimised with debug info. A unity
# build (CMAKE_UNITY_BUILD: each target's sources compiled as a few files, about a third less
# compile time): the Release build has compiled every file on its own, warnings as errors.
sanitize_build="$root/build-sanitize"
build_sanitize() {
    cmake -S "$root" -B "$sanitize_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVKBOOK_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON
    cmake --build "$sanitize_build" -j "$(nproc)"
}
# The tests not run again under the sanitizers, and why: tests/reliability/sanitizer/selection.sh
# (scripts/coverage.sh measures what the rest covers against the whole suite).
source "$root/tests/reliability/sanitizer/selection.sh"

# What each stage of `test` costs: its wall time and the CPU time (user + system) of everything it
# ran, read with the shell's `times` (the children it has waited for, their children included).
# `times` runs in this shell, never in $(...): a subshell's counts start at zero.
run_started=$SECONDS
stage_wall=0 stage_cpu=0 stage_times=""
read_times() {  # the CPU seconds `times` wrote to $stage_times, its second line (the children's)
    awk 'NR == 2 { for (i = 1; i <= 2; i++) { split($i, t, "m"); sub("s", "", t[2]); s += t[1] * 60 + t[2] } printf "%.0f", s }' \
        "$stage_times"
}
stage_start() {
    stage_wall=$SECONDS
    times > "$stage_times"
    stage_cpu=$(read_times)
}
stage_end() {  # stage_end NAME [JUNIT]
    times > "$stage_times"
    echo "setup: $1 took $((SECONDS - stage_wall)) s wall, $(($(read_times) - stage_cpu)) s CPU (user + system)"
    [ $# -lt 2 ] || python3 "$root/tests/tools/ctest_report.py" "$2" "$1"
}
# A test stage: its report also when a test failed, then the failure ends the command.
test_stage() {  # test_stage NAME JUNIT ctest-arguments...
    local name=$1 junit=$2 status=0
    shift 2
    stage_start
    ctest "$@" --output-junit "$junit" || status=$?
    stage_end "$name" "$junit"
    [ $status = 0 ] || { echo "setup: $name failed" >&2; exit $status; }
}

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
        stage_times=$(mktemp)
        trap 'rm -f "$stage_times"' EXIT
        stage_start
        install_missing
        stage_end "install"
        stage_start
        # Mesa 25's lavapipe beside the machine's own (unpacked into the build tree, never
        # installed): every chapter's golden images are checked on both drivers
        # (tests/desktops/second_driver.cmake).
        mkdir -p "$build"
        "$root/scripts/mesa_backports.sh" "$build/mesa-backports" > /dev/null
        build_release
        # The fuzz targets are test programs like the others: built here, not in the test stage
        # (their own clang tree; the target exists where clang can link them).
        # (grep reads the whole list: -q would stop early and fail the pipe under pipefail)
        if cmake --build "$build" --target help | grep 'fuzz-targets' > /dev/null; then
            cmake --build "$build" --target fuzz-targets
        fi
        stage_end "Release build (fuzz targets included)"
        # Two tests a core: many tests spend part of their time waiting (a window manager, a
        # reload, a reference image being compared), and the cores stay busy meanwhile. Every
        # test waits for events, not for a time, so a busier machine makes them slower, not red.
        jobs=$((2 * $(nproc)))
        test_stage "Release tests" "$build/ctest-junit.xml" --test-dir "$build" --output-on-failure -j "$jobs"
        stage_start
        build_sanitize
        stage_end "sanitizer build"
        test_stage "sanitizer tests" "$sanitize_build/ctest-junit.xml" --test-dir "$sanitize_build" \
            --output-on-failure -j "$jobs" -E "$sanitize_skip"
        stage_start
        "$root/scripts/windows-cross.sh" test
        stage_end "Windows (packages, sources, build, tests under Wine)" "$root/build-windows/ctest-junit.xml"
        echo "setup: the whole test command took $((SECONDS - run_started)) s"
        ;;
    *)
        echo "usage: scripts/setup.sh run [chapter-NN] [options...] | scripts/setup.sh test" >&2
        exit 2
        ;;
esac
