// What every loaded model must be, whatever the input (common/model/model.hpp's promises), checked by
// the loaders' fuzz targets (fuzz_obj, fuzz_gltf): a broken promise aborts the run.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "common/model/model.hpp"

namespace fuzz {

// A scratch directory of this process's own for the files a target writes, removed at exit:
// under $TMPDIR when set (tests/reliability/fuzz/run.sh points it at a directory it removes, since a crashing
// process leaves its directory behind), else /dev/shm, which is memory.
inline std::filesystem::path gScratch;
inline std::filesystem::path makeScratchDirectory(const char* target) {
    const char* tmpdir = std::getenv("TMPDIR");
    std::filesystem::path base = tmpdir && *tmpdir               ? tmpdir
                                 : access("/dev/shm", W_OK) == 0 ? "/dev/shm"
                                                                 : "/tmp";
    std::string pattern = (base / (std::string("vkbook-") + target + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data())) {
        std::perror("mkdtemp");
        std::abort();
    }
    gScratch = pattern;
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(gScratch, ec);
    });
    return gScratch;
}

[[noreturn]] inline void broken(const char* what) {
    std::fprintf(stderr, "fuzz: the model breaks a promise of ModelData: %s\n", what);
    std::abort();
}

inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool unit(const glm::vec3& v) {
    return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f;
}

// What model.hpp promises of every mesh: valid indices and finite, unit tangent frames.
inline void checkMesh(const common::MeshData& mesh, size_t materials) {
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

// The factors a glTF material hands the shaders: finite and in the ranges the specification
// gives them (an MTL file's Kd may say more than 1).
inline void checkMaterial(const common::MaterialData& m) {
    auto in01 = [](float x) { return std::isfinite(x) && x >= 0.0f && x <= 1.0f; };
    if (!in01(m.diffuse.r) || !in01(m.diffuse.g) || !in01(m.diffuse.b) || !in01(m.diffuse.a))
        broken("a base colour outside [0, 1]");
    if (!in01(m.roughness) || !in01(m.metallic)) broken("a roughness or metallic factor outside [0, 1]");
    if (!in01(m.occlusionStrength)) broken("an occlusion strength outside [0, 1]");
    if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0.0f)
        broken("a negative or non-finite alpha cutoff");
    if (!std::isfinite(m.normalScale)) broken("a non-finite normal scale");
}

inline void checkModel(const common::ModelData& model) {
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

}  // namespace fuzz
