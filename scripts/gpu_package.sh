#!/usr/bin/env bash
# Packs what a machine with a GPU but no compiler (or no Vulkan loader) needs to run the chapters
# headless and the benchmarks there: the Release binaries, shaders and scenes of BUILD_DIR/bin
# into .gpu/build/bin, the scene generator into .gpu/build/tools, and the Debian (amd64) runtime
# packages they load into .gpu/debs -- the Vulkan loader, GLFW and what it links, stb,
# tinyobjloader, tinygltf, a current libstdc++, the Khronos validation layer, so that --validation
# works there too, and time (bench/startup.sh reads peak memory with it); and the Sponza stand-in's
# generator into .gpu/build/bench/bin (bench/startup.sh writes the model there: it is too large to
# carry).
#
#   scripts/gpu_package.sh [BUILD_DIR]      (default: build, configured Release and built)
#
# On the GPU machine, from the repository root (with .gpu/ copied there):
#   for f in .gpu/debs/*.deb; do dpkg -x "$f" /; done; ldconfig
#   bench/light_scaling.sh --gpu .gpu/build OUT_DIR      (or bench/run.sh --gpu .gpu/build OUT_DIR,
#   bench/startup.sh .gpu/build 5 --device NVIDIA)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
packages=(libvulkan1 libglfw3 libx11-6 libxcb1 libxau6 libxdmcp6 libbsd0 libmd0 libgl1 libglvnd0 libglx0 libegl1
          libopengl0 libwayland-client0 libffi8 libstb0 libtinyobjloader2rc10 libtinygltf2d libstdc++6 libgcc-s1
          vulkan-validationlayers time)
lists=$(mktemp -d)
trap 'rm -rf "$lists"' EXIT
mkdir -p "$lists/partial" "$root/.gpu/debs" "$root/.gpu/build"
apt=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$lists")
apt-get "${apt[@]}" update > /dev/null
(cd "$root/.gpu/debs" && rm -f ./*.deb && apt-get "${apt[@]}" download "${packages[@]}" > /dev/null)
rm -rf "$root/.gpu/build/bin" "$root/.gpu/build/tools" "$root/.gpu/build/bench"
cp -r "$build/bin" "$root/.gpu/build/bin"
mkdir -p "$root/.gpu/build/tools"  # bench/light_scaling.sh makes scenes with it
cp "$build/tools/generate_light_scene" "$root/.gpu/build/tools/"
mkdir -p "$root/.gpu/build/bench/bin"
cp "$build/bench/bin/sponza_standin" "$root/.gpu/build/bench/bin/"
echo "gpu_package.sh: $(du -sh "$root/.gpu" | cut -f1) in .gpu"
