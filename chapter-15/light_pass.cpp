// chapter-15: the light pass.
#include "light_pass.hpp"

#include <algorithm>
#include <cstring>

#include "common/barriers.hpp"
#include "common/check.hpp"
#include "common/descriptors.hpp"
#include "common/files.hpp"
#include "common/pipeline.hpp"

namespace {

common::Image createOutput(const common::Device& device, VkExtent2D extent, LightPassKind kind) {
    // TRANSFER_SRC: --check-output copies it back to the CPU.
    VkImageUsageFlags written =
        kind == LightPassKind::Compute ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    return common::createImage(device, extent, kLightOutputFormat,
                               written | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT);
}

// The compute form writes the output through a storage-image descriptor, in GENERAL layout.
void writeOutput(const common::Device& device, LightPass& pass) {
    if (pass.kind != LightPassKind::Compute) return;
    VkDescriptorImageInfo image{.imageView = pass.output.view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                               .dstSet = pass.outputSet,
                               .dstBinding = 0,
                               .descriptorCount = 1,
                               .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                               .pImageInfo = &image};
    vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

// One binding per colour attachment in attachment order, then depth.
void writeAttachments(const common::Device& device, LightPass& pass, const common::GBuffer& gbuffer) {
    uint32_t binding = 0;
    for (const common::Image& color : gbuffer.colors)
        common::writeImageDescriptor(device, pass.attachmentsSet, binding++, pass.sampler, color.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    common::writeImageDescriptor(device, pass.attachmentsSet, binding, pass.sampler, gbuffer.depth.view,
                                 VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}

}  // namespace

LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GBuffer& gbuffer, GBufferLayout layout, LightPassKind kind,
                          uint32_t framesInFlight, uint32_t lightCapacity) {
    LightPass pass;
    pass.kind = kind;
    pass.output = createOutput(device, extent, kind);
    VkShaderStageFlags fragment =
        kind == LightPassKind::Compute ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    std::vector<VkDescriptorSetLayoutBinding> attachmentBindings;
    for (uint32_t i = 0; i <= gbuffer.colors.size(); ++i)  // the colour attachments, then depth
        attachmentBindings.push_back(common::binding(i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment));
    VkDescriptorSetLayoutCreateInfo attachmentsInfo{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .bindingCount = uint32_t(attachmentBindings.size()),
        .pBindings = attachmentBindings.data()};
    VK_CHECK(vkCreateDescriptorSetLayout(device.handle, &attachmentsInfo, nullptr, &pass.attachmentsLayout));
    pass.lightsLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fragment)});
    pass.sceneLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fragment)});
    pass.descriptorPool = common::createDescriptorPool(
        device, 2 + 2 * framesInFlight,
        {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(attachmentBindings.size())},
         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, framesInFlight},
         {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}});
    pass.attachmentsSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.attachmentsLayout);
    VkSamplerCreateInfo samplerInfo{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = VK_FILTER_NEAREST,  // one texel per pixel; depth formats need not filter linearly
        .minFilter = VK_FILTER_NEAREST,
        .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
    };
    VK_CHECK(vkCreateSampler(device.handle, &samplerInfo, nullptr, &pass.sampler));
    writeAttachments(device, pass, gbuffer);

    //> light-buffers
    // Lights and scene info change every frame (the keys move the lights, the camera moves):
    // one host-visible buffer of each per frame in flight. The lights buffer holds exactly the
    // scene's lights (one unused element when there are none: a buffer cannot be empty).
    pass.lightCapacity = lightCapacity;
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        pass.lights.push_back(common::createBuffer(device, std::max(lightCapacity, 1u) * sizeof(ShaderLight),
                                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hostVisible));
        pass.scenes.push_back(common::createBuffer(device, sizeof(ShaderSceneInfo),
                                                   VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, hostVisible));
        pass.lightSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.lightsLayout));
        pass.sceneSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.sceneLayout));
        common::writeBufferDescriptor(device, pass.lightSets.back(), 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                      pass.lights.back().handle, VK_WHOLE_SIZE);
        common::writeBufferDescriptor(device, pass.sceneSets.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      pass.scenes.back().handle, sizeof(ShaderSceneInfo));
    }
    //< light-buffers

    bool compact = layout == GBufferLayout::Compact;
    if (kind == LightPassKind::Fragment) {
        pass.pipeline = common::createFullscreenPipeline(
            device, cache, compact ? "chapter-15/light-compact.frag" : "chapter-15/light.frag",
            kLightOutputFormat, {pass.attachmentsLayout, pass.lightsLayout, pass.sceneLayout},
            sizeof(LightView));
        return pass;
    }

    //> compute-pipeline
    // The compute form: the same three sets plus set 3, the output as a storage image, and the
    // same push constants; one shader stage, no fixed-function state.
    pass.outputLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT)});
    pass.outputSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.outputLayout);
    writeOutput(device, pass);
    VkDescriptorSetLayout setLayouts[] = {pass.attachmentsLayout, pass.lightsLayout, pass.sceneLayout,
                                          pass.outputLayout};
    VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView)};
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                          .setLayoutCount = 4,
                                          .pSetLayouts = setLayouts,
                                          .pushConstantRangeCount = 1,
                                          .pPushConstantRanges = &pushRange};
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pass.computeLayout));
    VkShaderModule module =
        common::loadShaderModule(device, compact ? "chapter-15/light-compact.comp" : "chapter-15/light.comp");
    VkComputePipelineCreateInfo pipelineInfo{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module),
        .layout = pass.computeLayout,
    };
    VK_CHECK(
        vkCreateComputePipelines(device.handle, cache, 1, &pipelineInfo, nullptr, &pass.computePipeline));
    vkDestroyShaderModule(device.handle, module, nullptr);
    //< compute-pipeline
    return pass;
}

void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const common::GBuffer& gbuffer) {
    common::destroyImage(device, pass.output);
    pass.output = createOutput(device, extent, pass.kind);
    writeAttachments(device, pass, gbuffer);
    writeOutput(device, pass);
}

void updateLights(LightPass& pass, uint32_t frame, const std::vector<ShaderLight>& lights,
                  const ShaderSceneInfo& scene) {
    // std::copy_n, not memcpy: a scene with no lights has lights.data() == nullptr, which memcpy
    // must not be given even for 0 bytes (UndefinedBehaviorSanitizer reports it).
    uint32_t count = std::min<uint32_t>(uint32_t(lights.size()), pass.lightCapacity);
    std::copy_n(lights.data(), count, static_cast<ShaderLight*>(pass.lights[frame].mapped));
    ShaderSceneInfo info = scene;
    info.lightCount = count;
    std::memcpy(pass.scenes[frame].mapped, &info, sizeof(info));
}

//> record-compute-light
// The compute form: the output goes to GENERAL (a storage image), one 8x8 group per 8x8 pixels,
// then to READ_ONLY for the post pass -- the same image, the same layouts after, as the fragment form.
static void recordComputeLightPass(VkCommandBuffer cmd, const LightPass& pass,
                                   const VkDescriptorSet (&sets)[4], const LightView& view) {
    VkImageMemoryBarrier2 init = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.computePipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.computeLayout, 0, 4, sets, 0, nullptr);
    vkCmdPushConstants(cmd, pass.computeLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView), &view);
    vkCmdDispatch(cmd, (pass.output.extent.width + 7) / 8, (pass.output.extent.height + 7) / 8, 1);

    VkImageMemoryBarrier2 finish =
        common::imageBarrier(pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                             VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    common::pipelineBarrier(cmd, &finish, 1);
}
//< record-compute-light

//> record-light
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view) {
    VkDescriptorSet sets[] = {pass.attachmentsSet, pass.lightSets[frame], pass.sceneSets[frame],
                              pass.outputSet};
    if (pass.kind == LightPassKind::Compute) {
        recordComputeLightPass(cmd, pass, sets, view);
        return;
    }
    VkImageMemoryBarrier2 init = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    common::beginFullscreen(cmd, pass.output.view, pass.output.extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.layout, 0, 3, sets, 0,
                            nullptr);  // sets 0-2: the fourth is the compute form's
    vkCmdPushConstants(cmd, pass.pipeline.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LightView), &view);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);

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
    vkDestroyPipeline(device.handle, pass.computePipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.computeLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.outputLayout, nullptr);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    for (common::Buffer& buffer : pass.scenes) common::destroyBuffer(device, buffer);
    for (common::Buffer& buffer : pass.lights) common::destroyBuffer(device, buffer);
    vkDestroyDescriptorSetLayout(device.handle, pass.sceneLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.lightsLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.attachmentsLayout, nullptr);
    common::destroyImage(device, pass.output);
    pass = {};
}
