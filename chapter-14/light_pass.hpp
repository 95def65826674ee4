// chapter-14: the light pass -- the full-screen triangle into an offscreen R32G32B32A32_SFLOAT
// attachment, sampling the G-buffer. No lighting yet (it copies albedo, as the book does); the
// post pass turns the result into the presentation image. The book's RenderLight (chapter 14).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>

#include "common/passes/fullscreen.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "scene_pass.hpp"

inline constexpr VkFormat kLightOutputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// What the light pass shows (a fragment push constant).
// The twin of light.frag's LightView push-constant block (std430: three 4-byte scalars; the
// --view depth golden images would show a mismatch of near or far).
struct LightView {
    int view = 0;  // index into the chapter's --view names
    float near = 0.1f;
    float far = 100.0f;
};
static_assert(sizeof(LightView) == 12 && offsetof(LightView, near) == 4 && offsetof(LightView, far) == 8);

struct LightPass {
    common::Image output;  // one, shared by the frames in flight, like the G-buffer
    VkDescriptorSetLayout attachmentsLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet attachmentsSet = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    common::FullscreenPipeline pipeline;
};

LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const GBuffer& gbuffer);
void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const GBuffer& gbuffer);
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, const LightView& view);
void destroyLightPass(const common::Device& device, LightPass& pass);
