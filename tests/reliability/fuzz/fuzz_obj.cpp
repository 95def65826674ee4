// libFuzzer target: OBJ + MTL text through common::loadObjModel (tinyobjloader, our number checks,
// de-duplication, generated normals, computeTangents). Run by
// tests/reliability/fuzz/run.sh. The one acceptable failure is an InputError with a one-line message; any
// other exception, crash, sanitizer report or a model breaking ModelData's promises aborts the run.
//
// An input is the OBJ text, optionally followed by the line "#mtl" and the MTL text, which is
// written under the first name of the OBJ's first mtllib line (see corpus/obj/).
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "common/core/check.hpp"
#include "common/model/model.hpp"
#include "common/model/obj_model.hpp"
#include "model_checks.hpp"

namespace {

constexpr std::string_view kSeparator = "\n#mtl\n";

std::filesystem::path gDirectory;  // this process's own, under $TMPDIR or /dev/shm
bool gVerbose = false;             // VKBOOK_FUZZ_VERBOSE=1: say what became of each input

void writeFile(const std::filesystem::path& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), std::streamsize(text.size()));
    if (!out) {
        std::fprintf(stderr, "fuzz_obj: cannot write %s\n", path.c_str());
        std::abort();
    }
}

// The first name on the OBJ's first mtllib line when it is a plain file name that stays inside
// our directory; "model.mtl" otherwise (the OBJ then names a library that does not exist).
std::string mtlName(std::string_view obj) {
    const std::string_view fallback = "model.mtl";
    for (size_t start = 0; start < obj.size();) {
        size_t end = obj.find('\n', start);
        std::string_view line = obj.substr(start, end == std::string_view::npos ? end : end - start);
        start = end == std::string_view::npos ? obj.size() : end + 1;
        line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
        if (line.substr(0, 7) != "mtllib " && line.substr(0, 7) != "mtllib\t") continue;
        line.remove_prefix(7);
        line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
        std::string_view name = line.substr(0, line.find_first_of(" \t\r"));
        bool plain = !name.empty() && name.size() <= 64 && name != "." && name != ".." && name != "model.obj";
        for (char c : name)
            plain =
                plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-');
        return std::string(plain ? name : fallback);
    }
    return std::string(fallback);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = fuzz::makeScratchDirectory("fuzz-obj");
    gVerbose = std::getenv("VKBOOK_FUZZ_VERBOSE") != nullptr;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    size_t split = input.find(kSeparator);
    std::string_view obj = input.substr(0, split);
    std::filesystem::path objPath = gDirectory / "model.obj", mtlPath;
    writeFile(objPath, obj);
    if (split != std::string_view::npos) {
        mtlPath = gDirectory / mtlName(obj);
        writeFile(mtlPath, input.substr(split + kSeparator.size()));
    }
    try {
        common::ModelData model = common::loadObjModel(objPath);
        fuzz::checkModel(model);
        if (gVerbose) std::fprintf(stderr, "fuzz_obj: loaded, %zu meshes\n", model.meshes.size());
    } catch (const common::InputError& error) {
        if (gVerbose) std::fprintf(stderr, "fuzz_obj: InputError: %s\n", error.what());
        std::string_view message = error.what();
        if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
            std::fprintf(stderr, "fuzz_obj: InputError without a one-line message: '%s'\n", error.what());
            std::abort();
        }
    }
    std::error_code ec;
    if (!mtlPath.empty()) std::filesystem::remove(mtlPath, ec);
    return 0;
}
