// chapter-14: the light pass.
#include "light_pass.hpp"

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/texture.hpp"

namespace {

common::Image createOutput(const common::Device& device, VkExtent2D extent) {
    return common::createImage(device, extent, kLightOutputFormat,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT, "light output");
}

// The G-buffer, as light.frag samples it: binding 0 albedo, binding 1 depth.
void writeAttachments(const common::Device& device, LightPass& pass, const GBuffer& gbuffer) {
    common::writeImageDescriptor(device, pass.attachmentsSet, 0, pass.sampler, gbuffer.albedo.view,
                                 VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    common::writeImageDescriptor(device, pass.attachmentsSet, 1, pass.sampler, gbuffer.depth.view,
                                 VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}

}  // namespace

LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const GBuffer& gbuffer) {
    LightPass pass;
    pass.output = createOutput(device, extent);
    pass.attachmentsLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "light: G-buffer attachments");
    pass.descriptorPool =
        common::createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}}, "light");
    pass.attachmentsSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.attachmentsLayout,
                                                        "light: G-buffer attachments");
    // One texel per pixel: nearest filtering, which depth formats always support.
    pass.sampler =
        common::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    writeAttachments(device, pass, gbuffer);
    pass.pipeline =
        common::createFullscreenPipeline(device, cache, "chapter-14/light.frag", kLightOutputFormat,
                                         {pass.attachmentsLayout}, sizeof(LightView));
    return pass;
}

void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const GBuffer& gbuffer) {
    common::destroyImage(device, pass.output);
    pass.output = createOutput(device, extent);
    writeAttachments(device, pass, gbuffer);
}

//> record-light
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, const LightView& view) {
    // renderInit: the output to ATTACHMENT_OPTIMAL, once the previous frame's post pass has
    // finished sampling it (write after read). common::imageBarrier fills in the same
    // VkImageMemoryBarrier2 that scene_pass.cpp writes out.
    VkImageMemoryBarrier2 init = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    // One colour attachment, no depth; not loaded: the triangle covers every pixel. (Deliberate
    // repetition: common::beginFullscreen does the same for chapter-15's light pass.)
    VkRenderingAttachmentInfo output{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = pass.output.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
    };
    VkExtent2D extent = pass.output.extent;
    VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, extent},
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &output,
    };
    common::vk13.CmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.layout, 0, 1,
                            &pass.attachmentsSet, 0, nullptr);
    vkCmdPushConstants(cmd, pass.pipeline.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LightView), &view);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    common::vk13.CmdEndRendering(cmd);

    // renderFinish: to READ_ONLY_OPTIMAL, the writes visible to the post pass's fragment shader.
    VkImageMemoryBarrier2 finish = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    common::pipelineBarrier(cmd, &finish, 1);
}
//< record-light

void destroyLightPass(const common::Device& device, LightPass& pass) {
    common::destroyFullscreenPipeline(device, pass.pipeline);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.attachmentsLayout, nullptr);
    common::destroyImage(device, pass.output);
    pass = {};
}
