// chapter-17: the skinning pass -- the book's AnimRender. A compute shader (shaders/chapter-17/
// skin.comp) poses every animated model's skinned meshes once per frame, before the shadow and
// scene passes, into vertex buffers of their own (one per model instance and mesh: the book's
// per-entity buffers), which those passes then draw like any static mesh: one skinning serves every
// cascade and the scene pass. The joints' matrices are posed on the CPU (common/model/animation.hpp),
// in double, and uploaded once per frame with their normal matrices.
//
// Nothing of it exists when no model is animated; a frame whose pose did not change (paused, or a
// fixed --animation-time after the first frame) records no dispatch.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "common/model/animation.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

// The clock the animations play by (the book's EntityAnimation, by time instead of by frame): the
// clip and where in it, whether it plays, how fast. --animation-time fixes `seconds` and stops it.
struct AnimationClock {
    bool playing = true;
    int clip = 0;          // of each model's clips (a model with fewer plays its last)
    double seconds = 0.0;  // time played, looped into the clip by common::clipTime
    float speed = 1.0f;
};

// chapter-18's skinning (its skin.comp): the shader reads and writes through the buffers' device
// addresses, pushed with each dispatch, and has no descriptor sets (40 bytes, scalar layout).
struct SkinningAddresses {
    VkDeviceAddress bindPose = 0;    // the chunk's first bind-pose vertex
    VkDeviceAddress influences = 0;  // its first influence
    VkDeviceAddress palette = 0;     // the frame's palette, at the model's first joint
    VkDeviceAddress skinned = 0;     // its first posed vertex
    uint32_t count = 0;              // the chunk's vertices
    uint32_t padding = 0;
};
static_assert(sizeof(SkinningAddresses) == 40);

// The CPU side of one skinned mesh of one model instance.
struct SkinnedMesh {
    uint32_t sourceMesh = 0;  // GpuScene mesh with the bind pose (its vertex buffer is read)
    uint32_t outputMesh = 0;  // GpuScene mesh the draws use: its vertex buffer is written
    const common::MeshData* data = nullptr;
    uint32_t vertexCount = 0;
    common::Buffer influences;  // per vertex: 4 joints in 16 bits each, 4 weights (24 bytes)
    bool ownsInfluences = true;
    common::SkinBounds bounds;  // per joint, the bind-pose box of the vertices it moves
    // The vertices in chunks a binding and a dispatch can hold (skinning_pass.cpp), each with its
    // sets, one per frame in flight (the palette is per frame) -- or, with device addresses
    // (chapter-18), the addresses pushed for it, per frame in flight.
    struct Chunk {
        uint32_t first = 0, count = 0;
        std::vector<VkDescriptorSet> sets;
        std::vector<SkinningAddresses> addresses;
    };
    std::vector<Chunk> chunks;
};

// An animated model instance (the book's entity with an EntityAnimation).
struct SkinnedModel {
    uint32_t instance = 0;  // the scene's model
    std::string name;       // its file, for messages
    const common::ModelData* model = nullptr;
    uint32_t paletteBase = 0;  // its first joint in the palette buffer
    std::vector<SkinnedMesh> meshes;
    common::Pose pose;
};

// Vertices a vertex buffer written here holds beyond the mesh's, filled with a pattern that
// --check-skinning finds intact: an invocation past the mesh's end would write there first.
inline constexpr uint32_t kGuardVertices = 64;

// How the pass's shader reaches its buffers: chapter-17's descriptor sets, or chapter-18's device
// addresses (its buffers then made with SHADER_DEVICE_ADDRESS usage, and the posed vertices read by
// the vertex shader, which pulls them, instead of the vertex input).
struct SkinningOptions {
    std::string shader = "chapter-17/skin.comp";
    bool deviceAddresses = false;
};

struct SkinningPass {
    std::string shader = "chapter-17/skin.comp";
    bool deviceAddresses = false;
    std::vector<SkinnedModel> models;
    uint32_t paletteJoints = 0;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::vector<common::Buffer>
        palettes;                // common::PaletteEntry per joint, per frame in flight, host-visible
    uint32_t maxGroups = 65535;  // maxComputeWorkGroupCount[0]: a larger mesh takes more dispatches
    // Per frame in flight: the slot's frame poses differently from the buffers: dispatch. (Kept per
    // slot: chapter-20 poses the next frame while this one is recorded.)
    std::vector<uint8_t> dispatch;
    bool stale = true;      // the buffers hold no pose yet (or a reload made a new shader)
    double posedAt = -1.0;  // the clock time the buffers hold
    int posedClip = -1;
    uint64_t dispatchedFrames = 0;
    uint64_t vertices = 0;    // skinned per dispatching frame
    uint32_t dispatches = 0;  // vkCmdDispatch calls per dispatching frame
};

// Finds the scene's animated models (a rig and a skinned mesh), gives each skinned mesh of each of
// them a vertex buffer of its own and points their draws at it. Makes nothing when there are none.
SkinningPass createSkinningPass(const common::Device& device, VkPipelineCache cache, common::GpuScene& scene,
                                const common::Scene& sceneDesc, common::ModelCache& models,
                                uint32_t framesInFlight, const SkinningOptions& options = {});
// This frame's pose at `clock` into frame slot `slot`'s palette, and the skinned meshes' bounds;
// decides whether the pass records a dispatch this frame.
void poseSkinnedModels(SkinningPass& pass, common::GpuScene& scene, const AnimationClock& clock,
                       uint32_t slot);
void recordSkinningPass(VkCommandBuffer cmd, SkinningPass& pass, uint32_t slot);
void remakeSkinningPipeline(const common::Device& device, VkPipelineCache cache, SkinningPass& pass,
                            const common::ShaderReload& reload, common::PipelineSwap& swap);
// --check-skinning, after the last frame: every skinned vertex read back against the CPU's
// reference of the same pose (double precision), and the guard past each buffer intact. Prints the
// largest errors; throws Failure beyond the bound (docs/chapter-17.md).
void checkSkinning(const char* chapter, const common::Device& device, const SkinningPass& pass,
                   const common::GpuScene& scene);
// What the pass had to do, and did: for the report and --benchmark.
std::string describeSkinning(const SkinningPass& pass);
void destroySkinningPass(const common::Device& device, SkinningPass& pass);
