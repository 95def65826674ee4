// chapter-19: the book's GlobalBuffers -- what indirect drawing reads, per frame in flight, built on
// the host every frame: the draws' matrices, one InstanceData per instance drawn, and the draw
// commands (VkDrawIndirectCommand). The scene pass then records one vkCmdDrawIndirect per material
// (its pipeline and textures bound before it), each drawing all of that material's commands; the
// shadow pass the same per batch of the shadow cache's plan. A mesh that several draws share with one
// material (a model placed many times) is one command, its instanceCount the number of draws: the
// vertex shader finds each draw's matrices by gl_InstanceIndex (shaders/chapter-19/instances.glsl).
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

// What the vertex shaders read per instance (instances.glsl's Instance; scalar, 24 bytes). The
// book's holds the material index too; ours draws one material per indirect draw (its textures are
// bound per material: see docs/chapter-19.md), and carries the cascades a shadow draw goes to instead.
struct InstanceData {
    uint32_t matrix = 0;  // the draw's DrawConstants in the matrices buffer
    uint32_t layers = 0;  // shadow pass: bit i, cascade i; 0 in the scene pass
    VkDeviceAddress indices = 0;
    VkDeviceAddress vertices = 0;
};
static_assert(sizeof(InstanceData) == 24);

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

// One frame slot's buffers (host-visible and coherent: what the host writes is what the GPU reads).
struct FrameBuffers {
    GrowingBuffer matrices;                        // DrawConstants per draw of the scene
    GrowingBuffer instances;                       // InstanceData: the scene pass's, then the shadow pass's
    GrowingBuffer commands;                        // VkDrawIndirectCommand: the same
    uint32_t instanceCount = 0, commandCount = 0;  // written so far this frame
};

// The commands of one material: one vkCmdDrawIndirect (or more past maxDrawIndirectCount).
struct IndirectGroup {
    uint32_t material = 0;
    bool alphaTested = false;  // the shadow pass's cut-out pipeline
    uint32_t firstCommand = 0, commandCount = 0;
};

struct GlobalBuffers {
    std::vector<FrameBuffers> frames;  // per frame in flight
    std::vector<uint32_t> sceneOrder;  // the scene's draws by (opaque before cut-out, class, material, mesh)
    std::vector<IndirectGroup> sceneGroups;  // this frame's scene pass
    uint32_t maxDrawIndirectCount = 1;
    // What the last frame drew, for the report and the tests.
    uint32_t sceneCommands = 0, sceneInstances = 0, shadowCommands = 0, shadowInstances = 0;
    uint32_t sceneIndirectDraws = 0, shadowIndirectDraws = 0;
    uint64_t grown = 0;  // buffers made or made larger since the start
};

// The order the scene pass draws in: opaque materials' classes before cut-outs', then by class,
// material and mesh (`classOf`: each material's pipeline class), so that each material is one run
// and each mesh in it one command.
std::vector<uint32_t> sceneDrawOrder(const common::GpuScene& scene, const std::vector<uint32_t>& classOf);
// Commands for `draws` (draw index, cascades), in the order given, appended at `instanceCount` and
// `commandCount` of the two arrays: one command per run of draws of one mesh and material (its
// vertexCount the mesh's index count, its instances the run's), one group per run of one material.
void appendCommands(const common::GpuScene& scene, const std::vector<std::pair<uint32_t, uint32_t>>& draws,
                    InstanceData* instances, uint32_t& instanceCount, VkDrawIndirectCommand* commands,
                    uint32_t& commandCount, std::vector<IndirectGroup>& groups);

GlobalBuffers createGlobalBuffers(const common::Device& device, uint32_t framesInFlight);
// Frame slot `slot`'s matrices, the scene pass's instances and commands (its groups in
// `sceneGroups`), and room for `shadowDraws` more instances and commands (the shadow plan's draws).
// The slot's previous frame is done (its fence waited for): a buffer outgrown is destroyed and made
// anew at twice the size needed.
void updateGlobalBuffers(const common::Device& device, GlobalBuffers& buffers, uint32_t slot,
                         const common::GpuScene& scene, const ScenePass& scenePass, uint64_t shadowDraws);
// The scene pass's draws: per group its pipeline and textures bound, its material pushed, one
// vkCmdDrawIndirect (sets 0 and 1 bound by the pass).
void recordIndirectScene(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                         const ScenePass& scenePass);
// One batch of the shadow pass: its draws written as instances (with their cascades) and commands
// after what the frame holds, then drawn a vkCmdDrawIndirect per material.
void recordIndirectShadowBatch(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                               const ShadowPass& shadowPass, const ScenePass& scenePass,
                               const common::GpuScene& scene, const std::vector<ShadowDraw>& draws,
                               VkPipeline& bound);
// "N commands for M instances in K indirect draws" for the scene and shadow passes.
std::string describeGlobalBuffers(const GlobalBuffers& buffers);
void destroyGlobalBuffers(const common::Device& device, GlobalBuffers& buffers);
