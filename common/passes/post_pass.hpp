// The post pass: a light pass's output into the presentation image -- optional FXAA, clamped,
// sRGB-correct. Introduced by chapter-14 (the book's RenderPost) and used unchanged by chapter-15.
#pragma once

#include <vulkan/vulkan.h>

#include <array>

#include "common/passes/fullscreen.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/wnd/target.hpp"

namespace common {

struct PostPass {
    VkDescriptorSetLayout inputLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet inputSet = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    std::array<FullscreenPipeline, 2> pipelines;  // [0] without FXAA, [1] with (specialization constants)
};

// `lightOutput` is sampled in READ_ONLY_OPTIMAL; it must be filterable linearly for the best FXAA.
// `guiFollows`: a GUI pass draws over the image next and moves it to its present layout.
PostPass createPostPass(const Device& device, VkPipelineCache cache, VkFormat targetFormat,
                        const Image& lightOutput);
void resizePostPass(const Device& device, PostPass& pass, const Image& lightOutput);
// After the target was made again: when its format changed (the window moved to a screen with
// other formats), pipelines for the new one (its format and whether the shader sRGB-encodes).
// The device must be idle.
void retargetPostPass(const Device& device, VkPipelineCache cache, PostPass& pass, VkFormat targetFormat);
void recordPostPass(VkCommandBuffer cmd, const PostPass& pass, const Target& target, uint32_t imageIndex,
                    bool fxaa, bool guiFollows = false);
void destroyPostPass(const Device& device, PostPass& pass);
// Live reload: new pipelines into `swap` where the reload changed their shaders.
void remakePostPipelines(const Device& device, VkPipelineCache cache, PostPass& pass,
                         const ShaderReload& reload, PipelineSwap& swap);

}  // namespace common
