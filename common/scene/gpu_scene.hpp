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

#include "common/model/load_model.hpp"
#include "common/model/model.hpp"
#include "common/scene/scene.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"

namespace common {

struct GpuMesh {
    Buffer vertices;          // common::Vertex
    Buffer indices;           // uint32_t
    bool ownsIndices = true;  // false: another mesh's (a skinned copy of it draws them too)
    // Its shape changes from frame to frame (a skinned mesh playing): bounds updated by the
    // chapter, and casters drawn apart by chapter-16's shadow cache.
    bool deforms = false;
    // A mirrored copy (drawn by a scene transform of negative determinant): the same vertex
    // buffer, owned by the mesh it copies, with every triangle's winding turned around.
    bool ownsVertices = true;
    uint32_t indexCount = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // model space, to sort draws by distance
};

// A texture as a material binds it: an image of GpuScene::textures with a sampler of
// GpuScene::samplers.
struct TextureBinding {
    uint32_t image = 0;
    uint32_t sampler = 0;  // [0]: the default, trilinear and repeat
};
inline constexpr uint32_t kWhiteTexture = 0;       // GpuScene::textures[0]: 1x1 white
inline constexpr uint32_t kFlatNormalTexture = 1;  // GpuScene::textures[1]: 1x1 (0.5, 0.5, 1)

struct GpuMaterial {
    glm::vec4 diffuse{1.0f};
    float roughness = 1.0f;
    float metallic = 0.0f;
    TextureBinding albedo{kWhiteTexture};       // sRGB; alpha from map_d when given
    TextureBinding normal{kFlatNormalTexture};  // tangent-space normal map
    TextureBinding metalRough{kWhiteTexture};   // G = roughness, B = metallic, as in the book
    TextureBinding occlusion{kWhiteTexture};    // R = ambient occlusion (glTF)
    float normalScale = 1.0f;                   // glTF normalTexture.scale
    float occlusionStrength = 1.0f;             // glTF occlusionTexture.strength
    float alphaCutoff = 0.5f;                   // alpha below it is discarded when alphaTested
    bool alphaTested = false;  // a cut-out: glTF MASK (or BLEND); OBJ: some texel or the colour has alpha < 1
    bool doubleSided = false;  // drawn without back-face culling, back faces' normals flipped
};

struct Draw {
    uint32_t mesh = 0;
    uint32_t material = 0;
    glm::mat4 model{1.0f};
    uint32_t instance = 0;  // index of the scene's ModelInstance it draws (to move it later)
    // Derived from `model` once, by setDrawModel, not per frame: the inverse-transpose that
    // takes normals to world space, and the world-space centre of the mesh's bounds (draws are
    // ordered by its distance).
    glm::mat3 normalMatrix{1.0f};
    glm::vec3 center{0.0f};
};

struct GpuScene;
// Places a draw (at load time, or when its model moves, like a light's marker).
void setDrawModel(const GpuScene& scene, Draw& draw, const glm::mat4& model);

struct GpuScene {
    std::vector<GpuMesh> meshes;
    std::vector<Image> textures;        // [0]: 1x1 white, [1]: 1x1 flat normal (0.5, 0.5, 1)
    std::vector<bool> textureHasAlpha;  // per texture: some texel's alpha is below 1
    std::vector<VkSampler> samplers;    // [0]: the default; one per distinct glTF sampler
    std::vector<GpuMaterial> materials;
    std::vector<Draw> draws;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // world space
    uint64_t triangles = 0;                      // drawn per frame
};

// Which textures a chapter reads (the others are not loaded: chapter-10 only samples albedo), and
// whether it poses skinned meshes itself.
struct GpuSceneOptions {
    bool normalMaps = false;
    bool metalRoughMaps = false;
    bool occlusionMaps = false;
    // chapter-17 on: skinned meshes uploaded as stored, for the chapter's skinning pass to pose
    // (with STORAGE_BUFFER usage: the pass reads them). Before it: posed at rest on the CPU here,
    // with a warning that the model's animations are not played.
    bool skins = false;
    // chapter-18 on: vertex and index buffers made with SHADER_DEVICE_ADDRESS usage (their
    // Buffer::address), for vertex shaders that read them through pointers.
    bool deviceAddresses = false;
    // chapter-19 on: index buffers a transfer may copy from (TRANSFER_SRC usage): the chapter copies
    // every mesh's indices into one buffer.
    bool copyableIndices = false;
};

// Throws InputError (naming the file) for a bad model or a corrupt texture; a missing texture
// file falls back to the default texture with a warning on stderr. Images are decoded and their
// mip chains made on every core, and uploaded in batches of bounded size, so that a model's
// textures are never all in host memory at once (beside their device copies).
GpuScene loadGpuScene(const Device& device, const Scene& scene, ModelCache& models, GpuSceneOptions wanted);
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

//> material-classes
// Materials grouped by the pipeline they draw with: the distinct classes (what a pipeline's
// specialization constants are set from; any type with ==), in the order materials first use
// them, and each material's index into them. A scene pass makes one pipeline per class, so a
// scene pays only for the features its materials use; a material no draw uses adds no class.
template <typename Class>
struct MaterialClasses {
    static constexpr uint32_t kUnused = UINT32_MAX;
    std::vector<Class> classes;
    std::vector<uint32_t> ofMaterial;  // material index -> index into classes (kUnused: no draw)

    void add(const Class& materialClass, bool used) {  // the next material's class
        if (!used) {
            ofMaterial.push_back(kUnused);
            return;
        }
        uint32_t index = 0;
        while (index < classes.size() && !(classes[index] == materialClass)) ++index;
        if (index == classes.size()) classes.push_back(materialClass);
        ofMaterial.push_back(index);
    }
};
//< material-classes

// Per material of the scene: whether some draw uses it.
std::vector<bool> usedMaterials(const GpuScene& scene);

}  // namespace common
