// libFuzzer target: OBJ + MTL text through common::loadObjModel (tinyobjloader, our number checks,
// de-duplication, generated normals, computeTangents). Run by
// tests/fuzz/run.sh. The one acceptable failure is an InputError with a one-line message; any other
// exception, crash, sanitizer report or a model breaking ModelData's promises aborts the run.
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

#include "common/check.hpp"
#include "common/model.hpp"

namespace {

constexpr std::string_view kSeparator = "\n#mtl\n";

std::filesystem::path gDirectory;  // this process's own, under $TMPDIR or /dev/shm
bool gVerbose = false;             // VKBOOK_FUZZ_VERBOSE=1: say what became of each input

void removeDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(gDirectory, ec);
}

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

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_obj: the model breaks a promise of ModelData: %s\n", what);
    std::abort();
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool unit(const glm::vec3& v) {
    return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f;
}

// What model.hpp promises of every mesh: valid indices and finite, unit tangent frames.
void checkMesh(const common::MeshData& mesh, size_t materials) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) broken("indices are not whole triangles");
    if (mesh.material >= materials) broken("a mesh names a material that does not exist");
    for (uint32_t index : mesh.indices)
        if (index >= mesh.vertices.size()) broken("an index is out of range");
    for (const common::Vertex& v : mesh.vertices) {
        if (!finite(v.position) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y))
            broken("a non-finite position or uv");
        if (!unit(v.normal)) broken("a normal is not finite and unit length");
        if (!unit(v.tangent)) broken("a tangent is not finite and unit length");
        if (!unit(v.bitangent)) broken("a bitangent is not finite and unit length");
        if (std::abs(glm::dot(v.normal, v.tangent)) > 1e-3f)
            broken("a tangent is not orthogonal to its normal");
    }
}

void checkModel(const common::ModelData& model) {
    if (model.meshes.empty() || model.materials.empty()) broken("no meshes or no materials");
    if (!finite(model.boundsMin) || !finite(model.boundsMax) ||
        glm::any(glm::greaterThan(model.boundsMin, model.boundsMax)))
        broken("the bounds are not finite or not ordered");
    for (const common::MeshData& mesh : model.meshes) {
        checkMesh(mesh, model.materials.size());
        // computeTangents on its own, again over the loaded mesh: the same promises hold.
        common::MeshData again = mesh;
        common::computeTangents(again);
        checkMesh(again, model.materials.size());
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // $TMPDIR when set (tests/fuzz/run.sh points it at a directory it removes, since a crashing
    // process leaves its directory behind), else /dev/shm, which is memory.
    const char* tmpdir = std::getenv("TMPDIR");
    std::filesystem::path base = tmpdir && *tmpdir               ? tmpdir
                                 : access("/dev/shm", W_OK) == 0 ? "/dev/shm"
                                                                 : "/tmp";
    std::string pattern = (base / "vkbook-fuzz-obj-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
        std::perror("fuzz_obj: mkdtemp");
        std::abort();
    }
    gDirectory = pattern;
    gVerbose = std::getenv("VKBOOK_FUZZ_VERBOSE") != nullptr;
    std::atexit(removeDirectory);
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
        checkModel(model);
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
