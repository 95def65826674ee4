// A pipeline that draws the full-screen triangle into one colour attachment with dynamic
// rendering: what the light and post passes of chapters 14 and 15 have in common.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "common/shaders/shader_watch.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

namespace common {

struct FullscreenPipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    // What the pipeline is made from, to make it again when a shader is reloaded.
    std::string fragment;
    VkFormat outputFormat = VK_FORMAT_UNDEFINED;
    std::vector<VkSpecializationMapEntry> constants;
    std::vector<uint8_t> constantData;
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
// The pipeline made again with the 32-bit specialisation constant `id` set to `value` (added
// when it has no such constant), for the rest of the run and its reloads; the old one destroyed
// at once: the caller has waited for the device.
void respecializeFullscreenPipeline(const Device& device, VkPipelineCache cache, FullscreenPipeline& pipeline,
                                    uint32_t id, uint32_t value);

// Live reload: when `reload` changed fullscreen.vert or the pipeline's fragment shader, a new
// pipeline from the new code into `swap` (same layout, format and constants).
void remakeFullscreenPipeline(const Device& device, VkPipelineCache cache, FullscreenPipeline& pipeline,
                              const ShaderReload& reload, PipelineSwap& swap);

// Begins rendering into `view` (contents not loaded: the triangle covers every pixel) and sets
// the flipped viewport and the scissor.
void beginFullscreen(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent);

}  // namespace common
