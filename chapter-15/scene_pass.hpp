// chapter-15: the scene pass -- the scene into the book's PBR G-buffer: world position, albedo,
// normal (with normal maps) and PBR data (AO, roughness, metallic), all R16G16B16A16_SFLOAT,
// plus D32_SFLOAT depth: 36 bytes per pixel. The book's ScnRender and MrtAttachments.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/gbuffer.hpp"
#include "common/gpu_scene.hpp"

// Attachment order = the fragment shader's output locations = the light pass's bindings.
inline constexpr std::array<VkFormat, 4> kGBufferColorFormats = {
    VK_FORMAT_R16G16B16A16_SFLOAT,  // 0: world position
    VK_FORMAT_R16G16B16A16_SFLOAT,  // 1: albedo
    VK_FORMAT_R16G16B16A16_SFLOAT,  // 2: normal
    VK_FORMAT_R16G16B16A16_SFLOAT,  // 3: AO, roughness, metallic
};
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct ScenePass {
    common::GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout texturesLayout = VK_NULL_HANDLE;   // set 2: one per material, its 3 textures
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::Buffer> cameras;
    std::vector<VkDescriptorSet> cameraSets;
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialTextureSets;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight);
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame);
void destroyScenePass(const common::Device& device, ScenePass& pass);
