// Full-screen pipelines.
#include "common/fullscreen.hpp"

#include "common/check.hpp"
#include "common/debug_names.hpp"
#include "common/files.hpp"
#include "common/pipeline.hpp"
#include "common/shader_compiler.hpp"

namespace common {

FullscreenPipeline createFullscreenPipeline(const Device& device, VkPipelineCache cache, const char* fragment,
                                            VkFormat outputFormat,
                                            const std::vector<VkDescriptorSetLayout>& setLayouts,
                                            uint32_t pushConstantSize,
                                            const VkSpecializationInfo* specialization) {
    FullscreenPipeline result;
    VkPushConstantRange range{
        .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT, .offset = 0, .size = pushConstantSize};
    VkPipelineLayoutCreateInfo layoutInfo{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = uint32_t(setLayouts.size()),
        .pSetLayouts = setLayouts.data(),
        .pushConstantRangeCount = pushConstantSize ? 1u : 0u,
        .pPushConstantRanges = &range,
    };
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &result.layout));
    nameObject(device.handle, result.layout, fragment);

    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = 1,
        .pColorAttachmentFormats = &outputFormat,
    };
    VkShaderModule vertexModule = loadShaderModule(device, "common/fullscreen.vert");
    VkShaderModule fragmentModule = loadShaderModule(device, fragment);
    result.pipeline = createGraphicsPipeline(
        device, cache,
        {
            .name = fragment,
            .stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertexModule),
                       shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragmentModule, specialization)},
            .vertexInput = nullptr,  // the triangle comes from gl_VertexIndex
            .colorAttachmentCount = 1,
            .layout = result.layout,
            .pNext = &rendering,
        });
    vkDestroyShaderModule(device.handle, fragmentModule, nullptr);
    vkDestroyShaderModule(device.handle, vertexModule, nullptr);
    return result;
}

void destroyFullscreenPipeline(const Device& device, FullscreenPipeline& pipeline) {
    vkDestroyPipeline(device.handle, pipeline.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pipeline.layout, nullptr);
    pipeline = {};
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
