// The pipeline cache, persisted to a file between runs, and a graphics pipeline builder whose
// viewport and scissor are dynamic state. The book's PipelineCache and Pipeline (chapter 6).
#pragma once

#include <vulkan/vulkan.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/vk/device.hpp"

namespace common {

struct PipelineCache {
    VkPipelineCache handle = VK_NULL_HANDLE;
    std::filesystem::path file;  // where it is loaded from and saved to; empty: not persisted
};

// Where the cache of chapter `name` on this device lives, <cacheDir>/<name>-<vendor>-<device>.bin
// (empty when there is no cache directory), and its bytes when the file exists and was written by
// this very device and driver; a damaged or foreign file is ignored with a warning on stderr.
struct PipelineCacheFile {
    std::filesystem::path path;
    std::vector<char> data;  // empty: start with an empty cache
};
PipelineCacheFile readPipelineCacheFile(const Device& device, std::string_view name);

// readPipelineCacheFile, then vkCreatePipelineCache with its bytes (written out in chapter-06,
// which introduces it); a cache the driver refuses is replaced by an empty one, with a warning.
PipelineCache loadPipelineCache(const Device& device, std::string_view name);
// Writes the cache atomically (temporary file, then rename); a failure is only a warning.
void savePipelineCache(const Device& device, const PipelineCache& cache);
void destroyPipelineCache(const Device& device, PipelineCache& cache);

// A pipeline layout: the descriptor set layouts, set 0 first, and the push-constant ranges, named
// `name` (chapter-06 and chapter-10 write VkPipelineLayoutCreateInfo out).
VkPipelineLayout createPipelineLayout(const Device& device, std::span<const VkDescriptorSetLayout> sets,
                                      std::span<const VkPushConstantRange> pushConstants,
                                      const std::string& name);

// `specialization`, when given, sets the stage's constant_id constants (it must outlive pipeline creation).
VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, VkShaderModule module,
                                            const VkSpecializationInfo* specialization = nullptr);

// Everything that differs between the pipelines of these chapters; the rest is fixed: one
// sample, fill mode, no blending, and viewport + scissor set at record time (so a resize does
// not need a new pipeline).
struct GraphicsPipelineDesc {
    std::string name;  // what graphics debuggers and validation messages call it
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    const VkPipelineVertexInputStateCreateInfo* vertexInput = nullptr;  // nullptr: no vertex input
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = false;
    bool depthWrite = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    uint32_t colorAttachmentCount = 1;  // one blend state per colour attachment
    bool alphaBlend = false;            // blending off, or "over": colour by source alpha, alpha accumulated
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE;  // VK_NULL_HANDLE with dynamic rendering
    uint32_t subpass = 0;
    const void* pNext = nullptr;  // e.g. VkPipelineRenderingCreateInfo for dynamic rendering
};

VkPipeline createGraphicsPipeline(const Device& device, VkPipelineCache cache,
                                  const GraphicsPipelineDesc& desc);

// Live reload's build-then-swap (common/shaders/shader_watch.hpp): pipelines made from new shader code,
// each with the place of the one it replaces, while the old ones keep drawing. The layouts stay:
// a reload changes code only. Either all of them
// go in (swapPipelines) or none (discardPipelines).
struct PipelineSwap {
    std::vector<std::pair<VkPipeline*, VkPipeline>> pipelines;  // the place, the new pipeline
};
// Makes a pipeline with `make` and keeps it for `place` (make may throw: what was kept stays
// in the swap, for discardPipelines).
template <typename Make>
void replacePipeline(PipelineSwap& swap, VkPipeline& place, Make&& make) {
    swap.pipelines.emplace_back(&place, VK_NULL_HANDLE);
    swap.pipelines.back().second = make();
}
// The reload failed: destroys the new pipelines; the old ones stay.
void discardPipelines(const Device& device, PipelineSwap& swap);
// Puts the new pipelines in place of the old ones before frame `frame` is recorded. The frames in
// flight may still use the old ones, so they are retired, not destroyed: releaseRetiredPipelines
// destroys them once those frames are done (destroyDevice, whatever is left).
void swapPipelines(Device& device, PipelineSwap& swap, uint64_t frame);
// Once a frame, after waiting for the fence of frame `frame`'s slot: every frame up to
// frame - framesInFlight is done, and the pipelines retired before the one after it go.
void releaseRetiredPipelines(Device& device, uint64_t frame, uint32_t framesInFlight);

}  // namespace common
