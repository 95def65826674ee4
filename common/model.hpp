// Models on the CPU side: OBJ + MTL through tinyobjloader, triangulated, vertices de-duplicated,
// one mesh per material, with per-vertex tangents computed at load. The book's ModelLoader,
// ModelData, MeshData and Material (its chapters 7-9; tangents from chapter 15).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace common {

// The vertex every scene chapter uses. Its layout is described to Vulkan in common/gpu_scene.cpp
// (sceneVertexInput) and declared in the shaders as locations 0..4.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 tangent;    // unit, orthogonal to the normal, along +u of the texture
    glm::vec3 bitangent;  // unit, along +v of the OBJ's coordinates: up in the image (OpenGL normal maps)
    glm::vec2 uv;         // v flipped from the OBJ's, so v = 0 is the image's first row
};
static_assert(sizeof(Vertex) == 56, "Vertex is read by the GPU with this exact layout");

// What an MTL material says, with paths resolved against the MTL's directory.
struct MaterialData {
    std::string name;
    glm::vec4 diffuse{1.0f};                 // Kd, with d (dissolve) as alpha
    float roughness = 1.0f;                  // Pr
    float metallic = 0.0f;                   // Pm
    std::filesystem::path diffuseTexture;    // map_Kd
    std::filesystem::path normalTexture;     // norm, or bump / map_bump
    std::filesystem::path roughnessTexture;  // map_Pr
    std::filesystem::path metallicTexture;   // map_Pm
    std::filesystem::path alphaTexture;      // map_d
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    uint32_t material = 0;  // index into ModelData::materials
};

struct ModelData {
    std::vector<MeshData> meshes;
    std::vector<MaterialData> materials;  // at least one: a default white material
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

// Loads an OBJ file and the MTL files it names. Throws InputError with a one-line message naming
// the file on: a missing or unreadable file, an empty model, indices out of range, non-finite
// numbers, a missing material library.
ModelData loadObjModel(const std::filesystem::path& path);

// Models already read in this run, by path: a scene that places one OBJ many times, or --model
// (read once for its bounds, then uploaded), reads each file once.
using ModelCache = std::map<std::filesystem::path, ModelData>;
const ModelData& loadObjModelCached(ModelCache& cache, const std::filesystem::path& path);

// Computes per-vertex tangents and bitangents from positions, normals and UVs: per-triangle UV
// derivatives, accumulated per vertex, then made orthogonal to the normal (Gram-Schmidt).
// Zero-area triangles and degenerate UVs contribute nothing; a vertex left without a usable
// tangent gets an arbitrary unit vector orthogonal to its normal. The result is always finite.
void computeTangents(MeshData& mesh);

}  // namespace common
