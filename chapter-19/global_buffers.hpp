// chapter-19: the book's GlobalBuffers -- what indirect drawing reads, per frame in flight, built on
// the host every frame: the draws' matrices, one InstanceData per instance drawn, and the draw
// commands. The scene pass then records one indirect draw per material (its pipeline and textures
// bound before it), each drawing all of that material's commands; the shadow pass the same per batch
// of the shadow cache's plan. A mesh that several draws share with one material (a model placed many
// times) is one command, its instanceCount the number of draws: the vertex shader finds each draw's
// matrices by gl_InstanceIndex (shaders/chapter-19/instances.glsl).
//
// Where we differ from the book: its commands are VkDrawIndirectCommand over each mesh's index count,
// the shader reading the index through a pointer (chapter 18's way). Ours are
// VkDrawIndexedIndirectCommand into one index buffer holding every mesh's indices (each at its
// firstIndex), so that the GPU reuses a vertex shared by several triangles instead of shading it once
// per index (docs/chapter-18.md, "What pulling costs"); the vertices are still pulled.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "chapter-15/scene_pass.hpp"
#include "chapter-16/shadow_pass.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"

// What the vertex shaders read per instance (instances.glsl's Instance; scalar, 16 bytes). The
// book's holds the material index and the index buffer's address too; ours draws one material per
// indirect draw (its textures are bound per material: see docs/chapter-19.md) and reads indices from
// the bound index buffer, and carries the cascades a shadow draw goes to instead.
struct InstanceData {
    uint32_t matrix = 0;  // the draw's DrawConstants in the matrices buffer
    uint32_t layers = 0;  // shadow pass: bit i, cascade i; 0 in the scene pass
    VkDeviceAddress vertices = 0;
};
static_assert(sizeof(InstanceData) == 16);

// Every mesh's indices in one index buffer (made once, copied from the meshes' own on the GPU):
// mesh m's at firstIndex[m]. Meshes that share an index buffer share their place.
struct SceneIndices {
    common::Buffer buffer;
    std::vector<uint32_t> firstIndex;  // per GpuScene mesh
    uint64_t count = 0;
};
// Throws Failure past 2^32 indices in all (firstIndex is 32-bit).
SceneIndices createSceneIndices(const common::Device& device, const common::GpuScene& scene);
void destroySceneIndices(const common::Device& device, SceneIndices& indices);

// The vertex stage's push constants (instances.glsl's DrawBlock): 16 bytes; the fragment stage's
// material index follows at 16 (the fragment shaders compiled with DRAW_MATERIAL_OFFSET=16).
struct IndirectConstants {
    VkDeviceAddress instances = 0;
    VkDeviceAddress matrices = 0;
};
inline constexpr uint32_t kIndirectMaterialOffset = sizeof(IndirectConstants);
// The scene and shadow passes' pipelines for indirect drawing: no vertex input, the push ranges
// above. (Their draws are recorded by the hooks below, never one by one.)
inline constexpr MeshDrawing kIndirectMeshes{.vertexInput = false,
                                             .vertexConstants = sizeof(IndirectConstants),
                                             .materialOffset = kIndirectMaterialOffset,
                                             .record = nullptr};

// A buffer that grows by its capacity, never shrinks, and is made only when something is put in it.
struct GrowingBuffer {
    common::Buffer buffer;
    VkDeviceSize capacity = 0;  // bytes; 0: no buffer yet
};

// The commands of one material: one vkCmdDrawIndexedIndirect (or more past maxDrawIndirectCount).
struct IndirectGroup {
    uint32_t material = 0;
    bool alphaTested = false;  // the shadow pass's cut-out pipeline
    uint32_t firstCommand = 0, commandCount = 0;
};

// One frame slot's buffers (host-visible and coherent: what the host writes is what the GPU reads),
// and what its frame records from them. Everything a frame writes is its slot's: chapter-20 writes
// the next frame's slot while this one's is recorded.
struct FrameBuffers {
    GrowingBuffer matrices;                        // DrawConstants per draw of the scene
    GrowingBuffer instances;                       // InstanceData: the scene pass's, then the shadow pass's
    GrowingBuffer commands;                        // VkDrawIndexedIndirectCommand: the same
    uint32_t instanceCount = 0, commandCount = 0;  // written so far this frame
    std::vector<IndirectGroup> sceneGroups;        // the scene pass's
    // The shadow batches: which plan batch (its draws), and its groups.
    struct ShadowBatchGroups {
        const std::vector<ShadowDraw>* draws = nullptr;
        std::vector<IndirectGroup> groups;
    };
    std::vector<ShadowBatchGroups> shadowBatches;
    // What the frame drew, for the report and the tests.
    uint32_t sceneCommands = 0, sceneInstances = 0, shadowCommands = 0, shadowInstances = 0;
    uint32_t sceneIndirectDraws = 0, shadowIndirectDraws = 0;  // counted as they are recorded
};

struct GlobalBuffers {
    SceneIndices indices;              // what every command's indices index
    std::vector<FrameBuffers> frames;  // per frame in flight
    std::vector<uint32_t> sceneOrder;  // the scene's draws by (opaque before cut-out, class, material, mesh)
    uint32_t maxDrawIndirectCount = 1;
    uint32_t lastSlot = 0;  // the slot written last (the report's)
    uint64_t grown = 0;     // buffers made or made larger since the start
};

// The order the scene pass draws in: opaque materials' classes before cut-outs', then by class,
// material and mesh (`classOf`: each material's pipeline class), so that each material is one run
// and each mesh in it one command.
std::vector<uint32_t> sceneDrawOrder(const common::GpuScene& scene, const std::vector<uint32_t>& classOf);
// Commands for `draws` (draw index, cascades), in the order given, appended at `instanceCount` and
// `commandCount` of the two arrays: one command per run of draws of one mesh and material (its
// indices the mesh's, at `firstIndex[mesh]`; its instances the run's), one group per run of one
// material.
void appendCommands(const common::GpuScene& scene, const std::vector<uint32_t>& firstIndex,
                    const std::vector<std::pair<uint32_t, uint32_t>>& draws, InstanceData* instances,
                    uint32_t& instanceCount, VkDrawIndexedIndirectCommand* commands, uint32_t& commandCount,
                    std::vector<IndirectGroup>& groups);

// The scene's meshes as they are when the Render is made (the skinning pass's posed ones included).
GlobalBuffers createGlobalBuffers(const common::Device& device, const common::GpuScene& scene,
                                  uint32_t framesInFlight);
// Frame slot `slot`'s matrices, the scene pass's instances and commands (its groups in
// the slot's `sceneGroups`), and the shadow plan's, batch by batch (its `shadowBatches`: `plan` stays
// alive and unchanged until the frame is recorded). The slot's previous frame
// is done (its fence waited for): a buffer outgrown is destroyed and made anew at twice the size
// needed. All the host's work is here: recording only issues the draws.
void updateGlobalBuffers(const common::Device& device, GlobalBuffers& buffers, uint32_t slot,
                         const common::GpuScene& scene, const ScenePass& scenePass, const ShadowPlan& plan);
// The scene pass's draws: per group its pipeline and textures bound, its material pushed, one
// vkCmdDrawIndexedIndirect (sets 0 and 1 bound by the pass).
void recordIndirectScene(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                         const ScenePass& scenePass);
// One batch of the shadow pass (`draws`, one of the plan's batches): the groups updateGlobalBuffers
// wrote for it drawn, an indirect draw per material.
void recordIndirectShadowBatch(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                               const ShadowPass& shadowPass, const ScenePass& scenePass,
                               const std::vector<ShadowDraw>& draws, VkPipeline& bound);
// "N commands for M instances in K indirect draws" for the scene and shadow passes.
std::string describeGlobalBuffers(const GlobalBuffers& buffers);
void destroyGlobalBuffers(const common::Device& device, GlobalBuffers& buffers);
