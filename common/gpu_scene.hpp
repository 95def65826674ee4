// A scene on the GPU: every OBJ's meshes in device-local vertex and index buffers, every texture
// uploaded once, materials with the scene's overrides applied, and the list of draws (mesh,
// material, model matrix). Everything is sized from what the scene holds; all uploads go through
// one staging batch. The book's VulkanModel / TextureCache / MaterialsCache (chapters 7-9).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/image.hpp"
#include "common/model.hpp"
#include "common/scene.hpp"

namespace common {

struct GpuMesh {
    Buffer vertices;  // common::Vertex
    Buffer indices;   // uint32_t
    uint32_t indexCount = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // model space, to sort draws by distance
};

struct GpuMaterial {
    glm::vec4 diffuse{1.0f};
    float roughness = 1.0f;
    float metallic = 0.0f;
    uint32_t albedoTexture = 0;      // index into GpuScene::textures; alpha from map_d when given
    uint32_t normalTexture = 1;      // tangent-space normal map (a flat one when the MTL has none)
    uint32_t metalRoughTexture = 0;  // G = roughness, B = metallic, as in the book (white when none)
    bool alphaTested = false;        // some texel or the colour itself has alpha < 1: a cut-out (discard)
};

struct Draw {
    uint32_t mesh = 0;
    uint32_t material = 0;
    glm::mat4 model{1.0f};
    uint32_t instance = 0;  // index of the scene's ModelInstance it draws (to move it later)
};

struct GpuScene {
    std::vector<GpuMesh> meshes;
    std::vector<Image> textures;        // [0]: 1x1 white, [1]: 1x1 flat normal (0.5, 0.5, 1)
    std::vector<bool> textureHasAlpha;  // per texture: some texel's alpha is below 1
    std::vector<GpuMaterial> materials;
    std::vector<Draw> draws;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // world space
    uint64_t triangles = 0;                      // drawn per frame
};

// Which textures a chapter reads; the others are not loaded (chapter-10 only samples albedo).
struct GpuSceneTextures {
    bool normalMaps = false;
    bool metalRoughMaps = false;
};

// Throws InputError (naming the file) for a bad model or a corrupt texture; a missing texture
// file falls back to the default texture with a warning on stderr.
GpuScene loadGpuScene(const Device& device, const Scene& scene, ModelCache& models, GpuSceneTextures wanted);
void destroyGpuScene(const Device& device, GpuScene& scene);

// The vertex input of common::Vertex: binding 0, locations 0..4 = position, normal, tangent,
// bitangent, uv (the book's VertexBufferStructure from chapter 15 on). Only the attributes a
// pipeline's vertex shader consumes are described, so none is fetched for nothing.
enum VertexAttribute : uint32_t {
    kPosition = 1u << 0,
    kNormal = 1u << 1,
    kTangent = 1u << 2,
    kBitangent = 1u << 3,
    kUv = 1u << 4,
};
struct SceneVertexInput {
    VkVertexInputBindingDescription binding;
    std::array<VkVertexInputAttributeDescription, 5> attributes;
    VkPipelineVertexInputStateCreateInfo state;
};
void describeSceneVertexInput(SceneVertexInput& input, uint32_t attributes);

}  // namespace common
