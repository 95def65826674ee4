// chapter-15: the light pass -- Cook-Torrance lighting of the G-buffer by the scene's lights into
// an R32G32B32A32_SFLOAT image; the post pass (common/post_pass.cpp) presents it. The book's
// LightRender (chapter 15): a full-screen triangle. Beyond the book, --light-pass compute runs
// the same shading as a compute dispatch (beyond/compute_light_pass.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/fullscreen.hpp"
#include "common/gbuffer.hpp"
#include "common/image.hpp"
#include "gbuffer_layout.hpp"
#include "gpu_types.hpp"

inline constexpr VkFormat kLightOutputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// How the light pass runs: the book's full-screen triangle, or a compute dispatch.
enum class LightPassKind { Fragment, Compute };

// What the light pass owns per frame in flight: this frame's lights and scene info, host-visible
// (the keys move the lights, the camera moves), and the descriptor sets that bind them.
struct LightFrame {
    common::Buffer lights;  // scalar layout, ShaderLight[lightCapacity]
    common::Buffer scene;   // scalar layout, ShaderSceneInfo
    VkDescriptorSet lightsSet = VK_NULL_HANDLE;
    VkDescriptorSet sceneSet = VK_NULL_HANDLE;
};

struct LightPass {
    common::Image output;
    VkDescriptorSetLayout attachmentsLayout = VK_NULL_HANDLE;  // set 0: the G-buffer
    VkDescriptorSetLayout lightsLayout = VK_NULL_HANDLE;       // set 1: lights, per frame
    VkDescriptorSetLayout sceneLayout = VK_NULL_HANDLE;        // set 2: scene info, per frame
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet attachmentsSet = VK_NULL_HANDLE;
    std::vector<LightFrame> frames;
    uint32_t lightCapacity = 0;
    VkSampler sampler = VK_NULL_HANDLE;
    LightPassKind kind = LightPassKind::Fragment;
    common::FullscreenPipeline pipeline;  // Fragment
    // Compute (beyond/compute_light_pass.cpp): the output as a storage image (set 3), the pipeline.
    VkDescriptorSetLayout outputLayout = VK_NULL_HANDLE;
    VkDescriptorSet outputSet = VK_NULL_HANDLE;
    VkPipelineLayout computeLayout = VK_NULL_HANDLE;
    VkPipeline computePipeline = VK_NULL_HANDLE;
    // --light-culling tiled (beyond/light_culling.cpp): the tile lists' set layout, else null.
    VkDescriptorSetLayout tileLists = VK_NULL_HANDLE;
};

// `lightCapacity`: the scene's number of lights (the buffers are sized from it). `tileLists`:
// beyond the book, the tile lists' set layout for --light-culling tiled, else VK_NULL_HANDLE.
LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GBuffer& gbuffer, const GBufferLayout& layout, LightPassKind kind,
                          uint32_t framesInFlight, uint32_t lightCapacity,
                          VkDescriptorSetLayout tileLists = VK_NULL_HANDLE);
void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const common::GBuffer& gbuffer);
// Writes this frame's lights and scene info (lights.size() <= lightCapacity).
void updateLights(LightPass& pass, uint32_t frame, const std::vector<ShaderLight>& lights,
                  const ShaderSceneInfo& scene);
// `tileLists`: this frame's tile lists (--light-culling tiled), else VK_NULL_HANDLE.
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view,
                     VkDescriptorSet tileLists = VK_NULL_HANDLE);
void destroyLightPass(const common::Device& device, LightPass& pass);
