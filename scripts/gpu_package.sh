#!/usr/bin/env bash
# Packs what a machine with a GPU but no compiler (or no Vulkan loader) needs to run the chapters
# headless and the benchmarks there: the Release binaries, shaders and scenes of BUILD_DIR/bin
# into .gpu/build/bin, the scene generator into .gpu/build/tools, the Sponza stand-in's generator
# and the bandwidth probe (bench/run.sh --gpu) into .gpu/build/bench/bin (bench/startup.sh writes
# the model there: it is too large to carry), the glTF cases' generator (bench/specialisation.sh)
# and the shadow study's reference (bench/shadow_study.sh, where the build has it) into
# .gpu/build/tests/bin,
# and into .gpu/debs the Debian (amd64) packages of every shared library those programs load --
# found by ldd, each library mapped to its package with dpkg -S, so a library a chapter starts to
# load is packed without anyone listing it -- plus the Khronos validation layer (and what it loads),
# so that --validation works there too, and time (bench/startup.sh reads peak memory with it).
# The C library (libc6) is the machine's own. A library ldd cannot find, or one no installed
# package owns, stops the script with its name.
#
#   scripts/gpu_package.sh [BUILD_DIR]          (default: build, configured Release and built)
#   scripts/gpu_package.sh --list [BUILD_DIR]   prints the packages, one a line, downloads nothing
#
# On the GPU machine, from the repository root (with .gpu/ copied there):
#   for f in .gpu/debs/*.deb; do dpkg -x "$f" /; done; ldconfig
#   bench/light_scaling.sh --gpu .gpu/build OUT_DIR      (or bench/run.sh --gpu .gpu/build OUT_DIR,
#   bench/startup.sh .gpu/build 5 --device NVIDIA)
set -euo pipefail
list=0
if [ "${1:-}" = --list ]; then
    list=1
    shift
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
layer=$(dpkg -L vulkan-validationlayers 2>/dev/null | grep -m1 '/libVkLayer_khronos_validation\.so$' || true)
[ -n "$layer" ] || { echo "gpu_package.sh: vulkan-validationlayers is not installed" >&2; exit 1; }
# NVIDIA's Vulkan driver (libGLX_nvidia.so.0) loads GLVND's libraries when it starts, which no ldd
# of ours shows; without them vkCreateInstance finds no driver (VK_ERROR_INCOMPATIBLE_DRIVER, seen
# on the H100 machine). They are packed with what they load.
glvnd=()
for library in libGLdispatch.so.0 libGLX.so.0 libGL.so.1 libEGL.so.1 libOpenGL.so.0; do
    path=$(ldconfig -p | awk -v name="$library" '$1 == name && /x86-64/ {print $NF; exit}')
    [ -n "$path" ] || { echo "gpu_package.sh: $library is not installed (apt-get install libgl1 libegl1 libopengl0)" >&2; exit 1; }
    glvnd+=("$path")
done
programs=("$build"/bin/chapter-* "$build/tools/generate_light_scene" "$build/tools/generate_figure" "$build/bench/bin/sponza_standin"
          "$build/bench/bin/bandwidth" "$build/tests/bin/gltf_cases" "$layer" "${glvnd[@]}")
# bench/shadow_study.sh's reference, where this build has it (Embree found).
[ -x "$build/tests/bin/shadow_reference" ] && programs+=("$build/tests/bin/shadow_reference")
for program in "${programs[@]}"; do
    [ -f "$program" ] || { echo "gpu_package.sh: $program is missing (build it first)" >&2; exit 1; }
done

# The package that owns a library ldd resolved. Debian 12 merges /lib into /usr/lib, and a
# package registers its files under either: try the path as found, with /usr added or taken
# away, and the file a symbolic link points at. (dpkg -S also prints diversions; those lines are
# not owners.)
# Each path asked once (the programs share most of their libraries; dpkg -S takes a fifth of a
# second): owner sets $owned, in this shell (a $(...) would lose what it learnt).
declare -A owners=()
owner() {
    local path=$1 candidate found
    owned=${owners[$path]:-}
    [ -n "$owned" ] && return 0
    for candidate in "$path" "/usr$path" "${path#/usr}" "$(readlink -f "$path")"; do
        found=$(dpkg -S "$candidate" 2>/dev/null | grep -v '^diversion by ' | sed -n '1{s/: .*//;s/:[a-z0-9]*$//;p}')
        if [ -n "$found" ]; then
            owners[$path]=$found
            owned=$found
            return 0
        fi
    done
    return 1
}
declare -A packages=([vulkan-validationlayers]=1 [time]=1)
for program in "${programs[@]}"; do
    [ "$(head -c 4 "$program" | tail -c 3)" = ELF ] || continue  # scripts among the binaries
    # ldd's lines: "NAME => PATH (ADDRESS)", "NAME => not found", or a name alone (the vDSO, the
    # dynamic loader). PATH may hold spaces.
    while IFS= read -r line; do
        case $line in
            *" => not found"*)
                echo "gpu_package.sh: ${program#"$root"/} loads ${line%% =>*}, which ldd cannot find" >&2
                exit 1
                ;;
            *" => "*) ;;
            *) continue ;;
        esac
        path=${line#* => }
        path=${path% (0x*)}
        [ -n "$path" ] || continue
        owner "$path" || {
            echo "gpu_package.sh: ${program#"$root"/} loads $path, which no installed package owns" >&2
            exit 1
        }
        packages[$owned]=1
    done < <(ldd "$program" | sed 's/^[[:space:]]*//')
done
for library in "${glvnd[@]}"; do
    owner "$library" || { echo "gpu_package.sh: no installed package owns $library" >&2; exit 1; }
    packages[$owned]=1
done
unset 'packages[libc6]'
mapfile -t wanted < <(printf '%s\n' "${!packages[@]}" | sort)
if [ $list = 1 ]; then
    printf '%s\n' "${wanted[@]}"
    exit 0
fi

lists=$(mktemp -d)
trap 'rm -rf "$lists"' EXIT
mkdir -p "$lists/partial" "$root/.gpu/debs" "$root/.gpu/build"
apt=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$lists")
apt-get "${apt[@]}" update > /dev/null
(cd "$root/.gpu/debs" && rm -f ./*.deb && apt-get "${apt[@]}" download "${wanted[@]}" > /dev/null)
for package in "${wanted[@]}"; do
    compgen -G "$root/.gpu/debs/${package}_*.deb" > /dev/null ||
        { echo "gpu_package.sh: $package was not downloaded" >&2; exit 1; }
done
rm -rf "$root/.gpu/build/bin" "$root/.gpu/build/tools" "$root/.gpu/build/bench" "$root/.gpu/build/tests"
cp -r "$build/bin" "$root/.gpu/build/bin"
mkdir -p "$root/.gpu/build/tools"  # bench/light_scaling.sh makes scenes with it
cp "$build/tools/generate_light_scene" "$build/tools/generate_figure" "$root/.gpu/build/tools/"  # bench/animation.sh: the strip
mkdir -p "$root/.gpu/build/bench/bin"
cp "$build/bench/bin/sponza_standin" "$build/bench/bin/bandwidth" "$root/.gpu/build/bench/bin/"
mkdir -p "$root/.gpu/build/tests/bin"  # bench/specialisation.sh writes its glTF scene with it
cp "$build/tests/bin/gltf_cases" "$root/.gpu/build/tests/bin/"
[ -x "$build/tests/bin/shadow_reference" ] && cp "$build/tests/bin/shadow_reference" "$root/.gpu/build/tests/bin/"
echo "gpu_package.sh: ${#wanted[@]} packages; $(du -sh "$root/.gpu" | cut -f1) in .gpu"
