// chapter-10: the lighting pass.
#include "lighting_pass.hpp"

#include <string>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/formats.hpp"
#include "common/vk/pipeline.hpp"
#include "common/vk/texture.hpp"

namespace {

//> lighting-render-pass
// One colour attachment, the target image; the same set-up as chapter-06's render pass.
VkRenderPass createLightingRenderPass(const common::Device& device, const common::Target& target) {
    VkAttachmentDescription color{
        .format = target.format,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,  // the triangle covers every pixel
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
        .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
        .finalLayout = target.presentLayout,
    };
    VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{
        .pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
        .colorAttachmentCount = 1,
        .pColorAttachments = &colorRef,
    };
    // The image may only be written once the target has handed it over (the acquire semaphore
    // is waited at COLOR_ATTACHMENT_OUTPUT).
    VkSubpassDependency acquire{
        .srcSubpass = VK_SUBPASS_EXTERNAL,
        .dstSubpass = 0,
        .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        .srcAccessMask = 0,
        .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
    };
    VkRenderPassCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
        .attachmentCount = 1,
        .pAttachments = &color,
        .subpassCount = 1,
        .pSubpasses = &subpass,
        .dependencyCount = 1,
        .pDependencies = &acquire,
    };
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(device.handle, &info, nullptr, &renderPass));
    common::nameObject(device.handle, renderPass, "lighting");
    return renderPass;
}
//< lighting-render-pass

//> attachments-set
// The G-buffer as sampled images: binding 0 albedo, binding 1 depth, in the layouts the
// geometry pass left them in.
void writeAttachments(const common::Device& device, LightingPass& pass, const GBuffer& gbuffer) {
    common::writeImageDescriptor(device, pass.attachmentsSet, 0, pass.sampler, gbuffer.albedo.view,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    common::writeImageDescriptor(device, pass.attachmentsSet, 1, pass.sampler, gbuffer.depth.view,
                                 VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}
//< attachments-set

}  // namespace

namespace {

const std::vector<std::string> kLightingShaders{"chapter-10/lighting.vert", "chapter-10/lighting.frag"};

// The pipeline from the shaders' current code: at start-up, and again on a live reload.
VkPipeline makePipeline(const common::Device& device, VkPipelineCache cache, const LightingPass& pass,
                        VkFormat targetFormat) {
    common::ShaderModule vertex(device, kLightingShaders[0]);
    common::ShaderModule fragment(device, kLightingShaders[1]);
    // The shader writes the target image: it sRGB-encodes its colour itself where the image's
    // format does not (constant_id 0; chapter-06 introduces the same constant).
    VkBool32 encodeSrgb = common::encodesSrgb(targetFormat) ? VK_FALSE : VK_TRUE;
    VkSpecializationMapEntry encodeEntry{0, 0, sizeof(VkBool32)};
    VkSpecializationInfo fragmentConstants{1, &encodeEntry, sizeof(encodeSrgb), &encodeSrgb};
    // No vertex input at all (the book's EmptyVertexBufferStructure): the vertex shader makes
    // the triangle from gl_VertexIndex. No depth test either.
    return common::createGraphicsPipeline(
        device, cache,
        {
            .name = "lighting",
            .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                       common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment, &fragmentConstants)},
            .vertexInput = nullptr,
            .colorAttachmentCount = 1,
            .layout = pass.pipelineLayout,
            .renderPass = pass.renderPass,
        });
}

}  // namespace

LightingPass createLightingPass(const common::Device& device, VkPipelineCache cache,
                                const common::Target& target, const GBuffer& gbuffer) {
    LightingPass pass;
    pass.renderPass = createLightingRenderPass(device, target);
    pass.targetFormat = target.format;
    // One framebuffer per target image, as chapter-06 makes them (common/wnd/target.cpp).
    pass.framebuffers = common::createTargetFramebuffers(device, pass.renderPass, target);

    pass.attachmentsLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "lighting: G-buffer attachments");
    pass.descriptorPool =
        common::createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}}, "lighting");
    pass.attachmentsSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.attachmentsLayout,
                                                        "lighting: attachments");
    // Attachments are read one texel per pixel: nearest filtering, which every depth format
    // supports (linear filtering of D32_SFLOAT is optional).
    pass.sampler =
        common::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    writeAttachments(device, pass, gbuffer);

    VkPushConstantRange show{
        .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT, .offset = 0, .size = sizeof(LightingView)};
    VkPipelineLayoutCreateInfo layoutInfo{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = 1,
        .pSetLayouts = &pass.attachmentsLayout,
        .pushConstantRangeCount = 1,
        .pPushConstantRanges = &show,
    };
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pass.pipelineLayout));
    common::nameObject(device.handle, pass.pipelineLayout, "lighting");
    pass.pipeline = makePipeline(device, cache, pass, target.format);

    VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .queueFamilyIndex = device.queueFamily};
    VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &pass.commandPool));
    common::nameObject(device.handle, pass.commandPool, "lighting commands");
    return pass;
}

void resizeLightingPass(const common::Device& device, VkPipelineCache cache, LightingPass& pass,
                        const common::Target& target, const GBuffer& gbuffer) {
    common::destroyFramebuffers(device, pass.framebuffers);
    if (target.format != pass.targetFormat) {
        vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
        vkDestroyRenderPass(device.handle, pass.renderPass, nullptr);
        pass.pipeline = VK_NULL_HANDLE;
        pass.renderPass = VK_NULL_HANDLE;
        pass.renderPass = createLightingRenderPass(device, target);
        pass.targetFormat = target.format;
        pass.pipeline = makePipeline(device, cache, pass, target.format);
    }
    pass.framebuffers = common::createTargetFramebuffers(device, pass.renderPass, target);
    writeAttachments(device, pass, gbuffer);
}

bool remakeLightingPipeline(const common::Device& device, VkPipelineCache cache, LightingPass& pass,
                            const common::Target& target, const common::ShaderReload& reload,
                            common::PipelineSwap& swap) {
    if (!reload.changed(kLightingShaders)) return false;
    common::replacePipeline(swap, pass.pipeline,
                            [&] { return makePipeline(device, cache, pass, target.format); });
    return true;
}

//> record-lighting
void recordLightingPass(const common::Device& device, LightingPass& pass, const common::Target& target,
                        const LightingView& view) {
    // The number of target images can change with a resize: start from a fresh pool each time.
    VK_CHECK(vkResetCommandPool(device.handle, pass.commandPool, 0));
    if (pass.commandBuffers.size() != target.images.size()) {
        if (!pass.commandBuffers.empty())
            vkFreeCommandBuffers(device.handle, pass.commandPool, uint32_t(pass.commandBuffers.size()),
                                 pass.commandBuffers.data());
        pass.commandBuffers.resize(target.images.size());
        VkCommandBufferAllocateInfo allocInfo{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = pass.commandPool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = uint32_t(pass.commandBuffers.size()),
        };
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, pass.commandBuffers.data()));
        for (size_t i = 0; i < pass.commandBuffers.size(); ++i)
            common::nameObject(device.handle, pass.commandBuffers[i],
                               "lighting, target image " + std::to_string(i));
    }

    VkExtent2D extent = target.extent;
    for (size_t i = 0; i < pass.commandBuffers.size(); ++i) {
        VkCommandBuffer cmd = pass.commandBuffers[i];
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
        // Recorded once, so labelled here rather than by the frame loop's common::beginPass.
        common::beginLabel(cmd, "lighting");
        VkRenderPassBeginInfo begin{
            .sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
            .renderPass = pass.renderPass,
            .framebuffer = pass.framebuffers[i],
            .renderArea = {{0, 0}, extent},
        };
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
        VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f,
                            1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        VkRect2D scissor{{0, 0}, extent};
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 1,
                                &pass.attachmentsSet, 0, nullptr);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LightingView),
                           &view);
        vkCmdDraw(cmd, 3, 1, 0, 0);  // three vertices, no vertex buffer
        vkCmdEndRenderPass(cmd);
        common::endLabel(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));
    }
}
//< record-lighting

void destroyLightingPass(const common::Device& device, LightingPass& pass) {
    vkDestroyCommandPool(device.handle, pass.commandPool, nullptr);
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.attachmentsLayout, nullptr);
    common::destroyFramebuffers(device, pass.framebuffers);
    vkDestroyRenderPass(device.handle, pass.renderPass, nullptr);
    pass = {};
}
