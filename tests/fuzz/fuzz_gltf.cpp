// libFuzzer target: a glTF 2.0 file through common::loadGltfModel (our JSON and GLB checks,
// tinygltf's parser, the accessor reader, the node forest, strips and fans, generated normals and
// tangents, materials and samplers). Run by tests/fuzz/run.sh. The one acceptable failure is an
// InputError with a one-line message; any other exception, crash, sanitizer report or a model
// breaking ModelData's promises aborts the run.
//
// An input is the whole file: written as model.glb when it starts with the GLB magic "glTF",
// else as model.gltf, alone in a directory of its own, so that its buffers and images come from
// data: URIs or the GLB's binary chunk (an external URI names a file that does not exist).
#include <stdlib.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "common/check.hpp"
#include "common/model.hpp"
#include "model_checks.hpp"

namespace {

std::filesystem::path gDirectory;  // this process's own, under $TMPDIR or /dev/shm
bool gVerbose = false;             // VKBOOK_FUZZ_VERBOSE=1: say what became of each input

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = fuzz::makeScratchDirectory("fuzz-gltf");
    gVerbose = std::getenv("VKBOOK_FUZZ_VERBOSE") != nullptr;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    bool glb = input.substr(0, 4) == "glTF";
    std::filesystem::path path = gDirectory / (glb ? "model.glb" : "model.gltf");
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(input.data(), std::streamsize(input.size()));
        if (!out) {
            std::fprintf(stderr, "fuzz_gltf: cannot write %s\n", path.c_str());
            std::abort();
        }
    }
    try {
        common::ModelData model = common::loadGltfModel(path);
        fuzz::checkModel(model);
        for (const common::MaterialData& material : model.materials) fuzz::checkMaterial(material);
        if (gVerbose) std::fprintf(stderr, "fuzz_gltf: loaded, %zu meshes\n", model.meshes.size());
    } catch (const common::InputError& error) {
        if (gVerbose) std::fprintf(stderr, "fuzz_gltf: InputError: %s\n", error.what());
        std::string_view message = error.what();
        if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
            std::fprintf(stderr, "fuzz_gltf: InputError without a one-line message: '%s'\n", error.what());
            std::abort();
        }
    }
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return 0;
}
