// The post pass.
#include "common/passes/post_pass.hpp"

#include <cstddef>

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/formats.hpp"

namespace common {
namespace {

//> post-specialization
void createPostPipelines(const Device& device, VkPipelineCache cache, PostPass& pass, VkFormat targetFormat) {
    // Two variants of one shader: constant_id 0 switches FXAA, constant_id 1 the sRGB encoding
    // (only needed when the target format is not _SRGB, i.e. the hardware does not encode).
    struct Constants {
        VkBool32 fxaa;
        VkBool32 encodeSrgb;
    };
    std::array<VkSpecializationMapEntry, 2> entries{{
        {0, offsetof(Constants, fxaa), sizeof(VkBool32)},
        {1, offsetof(Constants, encodeSrgb), sizeof(VkBool32)},
    }};
    for (uint32_t fxaa = 0; fxaa < 2; ++fxaa) {
        Constants constants{fxaa, common::encodesSrgb(targetFormat) ? VK_FALSE : VK_TRUE};
        VkSpecializationInfo specialization{
            .mapEntryCount = uint32_t(entries.size()),
            .pMapEntries = entries.data(),
            .dataSize = sizeof(constants),
            .pData = &constants,
        };
        pass.pipelines[fxaa] = createFullscreenPipeline(device, cache, "common/post.frag", targetFormat,
                                                        {pass.inputLayout}, 0, &specialization);
    }
}
//< post-specialization

}  // namespace

PostPass createPostPass(const Device& device, VkPipelineCache cache, VkFormat targetFormat,
                        const Image& lightOutput) {
    PostPass pass;
    pass.inputLayout = createDescriptorSetLayout(
        device, {binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "post input");
    pass.descriptorPool =
        createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}}, "post");
    pass.inputSet = allocateDescriptorSet(device, pass.descriptorPool, pass.inputLayout, "post input");

    // FXAA's taps between texels need linear filtering, optional for 32-bit float formats.
    // SHORTCUT: where it is missing, FXAA runs on nearest samples and smooths less.
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, lightOutput.format, &properties);
    VkFilter filter = (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
                          ? VK_FILTER_LINEAR
                          : VK_FILTER_NEAREST;
    VkSamplerCreateInfo samplerInfo{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = filter,
        .minFilter = filter,
        .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
    };
    VK_CHECK(vkCreateSampler(device.handle, &samplerInfo, nullptr, &pass.sampler));
    nameObject(device.handle, pass.sampler, "post: input sampler");
    resizePostPass(device, pass, lightOutput);

    createPostPipelines(device, cache, pass, targetFormat);
    return pass;
}

void retargetPostPass(const Device& device, VkPipelineCache cache, PostPass& pass, VkFormat targetFormat) {
    if (pass.pipelines[0].outputFormat == targetFormat) return;
    for (FullscreenPipeline& pipeline : pass.pipelines) destroyFullscreenPipeline(device, pipeline);
    createPostPipelines(device, cache, pass, targetFormat);
}

void resizePostPass(const Device& device, PostPass& pass, const Image& lightOutput) {
    writeImageDescriptor(device, pass.inputSet, 0, pass.sampler, lightOutput.view,
                         VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}

//> record-post
void recordPostPass(VkCommandBuffer cmd, const PostPass& pass, const Target& target, uint32_t imageIndex,
                    bool fxaa, bool guiFollows) {
    VkImage image = target.images[imageIndex];
    // renderInit: the target image to ATTACHMENT_OPTIMAL. The submission waits for the image at
    // COLOR_ATTACHMENT_OUTPUT; starting the transition at that same stage chains it to the wait.
    VkImageMemoryBarrier2 init = imageBarrier(
        image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    pipelineBarrier(cmd, &init, 1);

    const FullscreenPipeline& pipeline = pass.pipelines[fxaa ? 1 : 0];
    beginFullscreen(cmd, target.views[imageIndex], target.extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout, 0, 1, &pass.inputSet, 0,
                            nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vk13.CmdEndRendering(cmd);

    // The GUI pass draws over the image next: it stays in ATTACHMENT_OPTIMAL, and the GUI pass
    // orders itself after these writes and moves it on.
    if (guiFollows) return;
    // renderFinish: to the layout the target presents from. Nothing later in this command buffer
    // touches it; the submission's signal covers the rest.
    VkImageMemoryBarrier2 finish =
        imageBarrier(image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                     target.presentLayout, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    pipelineBarrier(cmd, &finish, 1);
}
//< record-post

void remakePostPipelines(const Device& device, VkPipelineCache cache, PostPass& pass,
                         const ShaderReload& reload, PipelineSwap& swap) {
    for (FullscreenPipeline& pipeline : pass.pipelines)
        remakeFullscreenPipeline(device, cache, pipeline, reload, swap);
}

void destroyPostPass(const Device& device, PostPass& pass) {
    for (FullscreenPipeline& pipeline : pass.pipelines) destroyFullscreenPipeline(device, pipeline);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.inputLayout, nullptr);
    pass = {};
}

}  // namespace common
