// chapter-15: the scene pass -- the scene into the book's PBR G-buffer: world position, albedo,
// normal (with normal maps) and PBR data (AO, roughness, metallic), all R16G16B16A16_SFLOAT,
// plus D32_SFLOAT depth: 36 bytes per pixel (gbuffer_layout.hpp). The book's ScnRender and
// MrtAttachments. The G-buffer's barriers and vkCmdBeginRendering are chapter-14's, from
// common/gbuffer.cpp.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/camera.hpp"
#include "common/device.hpp"
#include "common/gbuffer.hpp"
#include "common/gpu_scene.hpp"
#include "common/pipeline.hpp"
#include "common/shader_watch.hpp"
#include "gbuffer_layout.hpp"

// The compiled shaders of a scene pipeline, files under <build>/bin/shaders/: the book's by
// default. A fragment shader starts from scene_surface.glsl's sceneSurface().
struct SceneShaders {
    std::string vertex = "chapter-15/scene.vert";
    std::string fragment = "chapter-15/scene.frag";
};

// What a scene pipeline draws into, and with which shaders.
struct ScenePipelineTarget {
    SceneShaders shaders;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
    bool reversedZ = false;
    std::vector<VkDescriptorSetLayout> moreSets;  // sets 3.. after the scene pass's own
};

// The scene's pipelines from one fragment shader: without the alpha test (opaque materials:
// early depth testing) and with it (cut-outs); each with back faces culled, and without culling
// for double-sided materials (glTF's doubleSided).
struct ScenePipelines {
    VkPipelineLayout layout = VK_NULL_HANDLE;  // sets 0-2 (camera, materials, textures), then any more
    VkPipeline opaque = VK_NULL_HANDLE;
    VkPipeline cutout = VK_NULL_HANDLE;
    VkPipeline opaqueDoubleSided = VK_NULL_HANDLE;
    VkPipeline cutoutDoubleSided = VK_NULL_HANDLE;
    ScenePipelineTarget target;  // what they were made for, to make them again on a reload
};

struct ScenePass {
    const GBufferLayout* layout = &kBookGBuffer;
    common::GBufferFormats formats;  // the layout's, with the depth format this device renders to
    common::GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout texturesLayout = VK_NULL_HANDLE;   // set 2: one per material, its 4 textures
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::CameraFrame> cameras;  // per frame in flight
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialTextureSets;
    ScenePipelines pipelines;
    std::vector<uint32_t> order;  // the draws' indices in the order they are recorded
    glm::vec3 orderedFrom{0.0f};  // the camera position `order` was made for
};

// The G-buffer of `layout` and the pipelines that fill it (none for a layout of depth alone).
// Throws Failure when the device cannot render to the layout's formats (for depth: to D32_SFLOAT
// or X8_D24_UNORM_PACK32, or to D32_SFLOAT for a reversed-Z layout).
ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight,
                          const GBufferLayout& layout = kBookGBuffer, const SceneShaders& shaders = {});
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
// Opaque draws nearest first (so hidden fragments fail the depth test before shading), then cut-outs.
void recordScenePass(VkCommandBuffer cmd, ScenePass& pass, const common::GpuScene& scene, uint32_t frame,
                     glm::vec3 cameraPosition);
void destroyScenePass(const common::Device& device, ScenePass& pass);

// The scene pass's pipelines for a target and shaders (createScenePass makes the G-buffer's), and
// the scene's draws recorded with them (sets 0 and 1, and any more, bound by the caller).
ScenePipelines createScenePipelines(const common::Device& device, VkPipelineCache cache,
                                    const ScenePass& pass, const ScenePipelineTarget& target);
void recordSceneDraws(VkCommandBuffer cmd, ScenePass& pass, const ScenePipelines& pipelines,
                      const common::GpuScene& scene, glm::vec3 cameraPosition);
void destroyScenePipelines(const common::Device& device, ScenePipelines& pipelines);
// Live reload: new pipelines into `swap` when the reload changed their shaders.
void remakeScenePipelines(const common::Device& device, VkPipelineCache cache, ScenePipelines& pipelines,
                          const common::ShaderReload& reload, common::PipelineSwap& swap);
