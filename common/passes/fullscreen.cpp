// Full-screen pipelines.
#include "common/passes/fullscreen.hpp"

#include <algorithm>
#include <cstring>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/pipeline.hpp"

namespace common {
namespace {

std::vector<std::string> shadersOf(const FullscreenPipeline& pipeline) {
    return {"common/fullscreen.vert", pipeline.fragment};
}

VkPipeline makePipeline(const Device& device, VkPipelineCache cache, const FullscreenPipeline& made) {
    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = 1,
        .pColorAttachmentFormats = &made.outputFormat,
    };
    VkSpecializationInfo specialization{
        .mapEntryCount = uint32_t(made.constants.size()),
        .pMapEntries = made.constants.data(),
        .dataSize = made.constantData.size(),
        .pData = made.constantData.data(),
    };
    ShaderModule vertex(device, "common/fullscreen.vert");
    ShaderModule fragment(device, made.fragment);
    return createGraphicsPipeline(
        device, cache,
        {
            .name = made.fragment,
            .stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                       shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment,
                                   made.constants.empty() ? nullptr : &specialization)},
            .vertexInput = nullptr,  // the triangle comes from gl_VertexIndex
            .colorAttachmentCount = 1,
            .layout = made.layout,
            .pNext = &rendering,
        });
}

}  // namespace

FullscreenPipeline createFullscreenPipeline(const Device& device, VkPipelineCache cache, const char* fragment,
                                            VkFormat outputFormat,
                                            const std::vector<VkDescriptorSetLayout>& setLayouts,
                                            uint32_t pushConstantSize,
                                            const VkSpecializationInfo* specialization) {
    FullscreenPipeline result;
    VkPushConstantRange range{
        .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT, .offset = 0, .size = pushConstantSize};
    result.layout = createPipelineLayout(device, setLayouts, {&range, pushConstantSize ? 1u : 0u}, fragment);

    result.fragment = fragment;
    result.outputFormat = outputFormat;
    if (specialization) {
        result.constants.assign(specialization->pMapEntries,
                                specialization->pMapEntries + specialization->mapEntryCount);
        const auto* data = static_cast<const uint8_t*>(specialization->pData);
        result.constantData.assign(data, data + specialization->dataSize);
    }
    result.pipeline = makePipeline(device, cache, result);
    return result;
}

void respecializeFullscreenPipeline(const Device& device, VkPipelineCache cache, FullscreenPipeline& pipeline,
                                    uint32_t id, uint32_t value) {
    FullscreenPipeline changed = pipeline;  // the pipeline keeps its constants if this one fails
    auto entry = std::find_if(changed.constants.begin(), changed.constants.end(),
                              [&](const VkSpecializationMapEntry& e) { return e.constantID == id; });
    if (entry == changed.constants.end()) {
        changed.constants.push_back({id, uint32_t(changed.constantData.size()), sizeof(uint32_t)});
        changed.constantData.resize(changed.constantData.size() + sizeof(uint32_t));
        entry = changed.constants.end() - 1;
    }
    std::memcpy(changed.constantData.data() + entry->offset, &value, sizeof(uint32_t));
    changed.pipeline = makePipeline(device, cache, changed);
    vkDestroyPipeline(device.handle, pipeline.pipeline, nullptr);
    pipeline = std::move(changed);
}

void destroyFullscreenPipeline(const Device& device, FullscreenPipeline& pipeline) {
    vkDestroyPipeline(device.handle, pipeline.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pipeline.layout, nullptr);
    pipeline = {};
}

void remakeFullscreenPipeline(const Device& device, VkPipelineCache cache, FullscreenPipeline& pipeline,
                              const ShaderReload& reload, PipelineSwap& swap) {
    if (pipeline.pipeline == VK_NULL_HANDLE || !reload.changed(shadersOf(pipeline))) return;
    replacePipeline(swap, pipeline.pipeline, [&] { return makePipeline(device, cache, pipeline); });
}

void beginFullscreen(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent) {
    VkRenderingAttachmentInfo color{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
    };
    VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, extent},
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &color,
    };
    vk13.CmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace common
