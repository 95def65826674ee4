// A pipeline that draws the full-screen triangle into one colour attachment with dynamic
// rendering: what the light and post passes of chapters 14 and 15 have in common.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "common/device.hpp"

namespace common {

struct FullscreenPipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// `fragment` names a shader under shaders/ (e.g. "chapter-14/light.frag"); the vertex shader is
// shaders/common/fullscreen.vert. `setLayouts` are sets 0, 1, ...;
// `pushConstantSize` bytes of fragment push constants (0 for none).
FullscreenPipeline createFullscreenPipeline(const Device& device, VkPipelineCache cache, const char* fragment,
                                            VkFormat outputFormat,
                                            const std::vector<VkDescriptorSetLayout>& setLayouts,
                                            uint32_t pushConstantSize,
                                            const VkSpecializationInfo* specialization = nullptr);
void destroyFullscreenPipeline(const Device& device, FullscreenPipeline& pipeline);

// Begins rendering into `view` (contents not loaded: the triangle covers every pixel) and sets
// the flipped viewport and the scissor.
void beginFullscreen(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent);

}  // namespace common
