// chapter-14: the scene pass -- the scene into the G-buffer with dynamic rendering: no render
// pass and no framebuffer; the attachments are named when rendering begins, and barriers move
// them between layouts before and after. The book's RenderScn (chapter 14), with its
// renderInit / renderFinish.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include <glm/glm.hpp>

#include "common/passes/camera_frames.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/pipeline.hpp"

//> gbuffer
// This chapter's G-buffer: albedo and depth (chapter-15 adds position, normal and PBR data). One,
// shared by all frames in flight: the scene pass of a frame and the light pass that reads it are
// in the same command buffer, and the barriers order every frame's use after the previous one's.
// Depth is D32_SFLOAT where the device can render to it, else X8_D24_UNORM_PACK32
// (common::chooseDepthFormat); the format is in depth.format.
inline constexpr VkFormat kAlbedoFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

struct GBuffer {
    common::Image albedo;
    common::Image depth;
};
//< gbuffer

// A material as scene.frag reads it (std430): the colour, and the alpha below which a texel is
// discarded (0: never).
struct SceneMaterial {
    glm::vec4 diffuse;
    float alphaCutoff;
    float padding[3];
};
static_assert(sizeof(SceneMaterial) == 32);

// A material class: what a scene pipeline is specialised for (scene.frag's constants).
struct MaterialClass {
    bool alphaTest = true;     // a cut-out
    bool baseColorMap = true;  // has a texture
    bool operator==(const MaterialClass&) const = default;
};

struct ScenePass {
    GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout textureLayout = VK_NULL_HANDLE;    // set 2: one per material, its albedo texture
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::CameraFrame> cameras;  // per frame in flight
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> textureSets;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    common::MaterialClasses<MaterialClass> materialClasses;  // the classes, and each material's
    std::vector<VkPipeline> pipelines;                       // one per class
};

// `generic` (--pipelines generic): one pipeline, with the alpha test and the texture, for every
// material; otherwise one per material class the scene has.
ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight, bool generic = false);
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame);
// Live reload: new pipelines into `swap` when the reload changed scene.vert or scene.frag.
void remakeScenePipeline(const common::Device& device, VkPipelineCache cache, ScenePass& pass,
                         const common::ShaderReload& reload, common::PipelineSwap& swap);
void destroyScenePass(const common::Device& device, ScenePass& pass);
