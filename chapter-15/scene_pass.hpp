// chapter-15: the scene pass -- the scene into the book's PBR G-buffer: world position, albedo,
// normal (with normal maps) and PBR data (AO, roughness, metallic), all R16G16B16A16_SFLOAT,
// plus D32_SFLOAT depth: 36 bytes per pixel (gbuffer_layout.hpp). The book's ScnRender and
// MrtAttachments. The G-buffer's barriers and vkCmdBeginRendering are chapter-14's, from
// common/gbuffer.cpp.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/camera.hpp"
#include "common/device.hpp"
#include "common/gbuffer.hpp"
#include "common/gpu_scene.hpp"
#include "gbuffer_layout.hpp"

struct ScenePass {
    const GBufferLayout* layout = &kBookGBuffer;
    common::GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout texturesLayout = VK_NULL_HANDLE;   // set 2: one per material, its 3 textures
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::CameraFrame> cameras;  // per frame in flight
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialTextureSets;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline opaquePipeline = VK_NULL_HANDLE;  // no alpha test: early depth testing
    VkPipeline cutoutPipeline = VK_NULL_HANDLE;  // alpha-tested materials
};

// Throws Failure when the device cannot render to the layout's formats.
ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight,
                          const GBufferLayout& layout);
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
// Opaque draws nearest first (so hidden fragments fail the depth test before shading), then cut-outs.
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame, glm::vec3 cameraPosition);
void destroyScenePass(const common::Device& device, ScenePass& pass);
