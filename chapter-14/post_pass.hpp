// chapter-14: the post pass -- the light output into the presentation image: optional FXAA,
// clamped, sRGB-correct. The book's RenderPost.
#pragma once

#include <vulkan/vulkan.h>

#include <array>

#include "common/device.hpp"
#include "common/image.hpp"
#include "common/target.hpp"
#include "fullscreen.hpp"

struct PostPass {
    VkDescriptorSetLayout inputLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet inputSet = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    std::array<FullscreenPipeline, 2> pipelines;  // [0] without FXAA, [1] with (specialization constants)
};

PostPass createPostPass(const common::Device& device, VkPipelineCache cache, VkFormat targetFormat,
                        const common::Image& lightOutput);
void resizePostPass(const common::Device& device, PostPass& pass, const common::Image& lightOutput);
void recordPostPass(VkCommandBuffer cmd, const PostPass& pass, const common::Target& target,
                    uint32_t imageIndex, bool fxaa);
void destroyPostPass(const common::Device& device, PostPass& pass);
