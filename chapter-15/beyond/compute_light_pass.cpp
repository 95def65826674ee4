// chapter-15, beyond the book: the compute light pass.
#include "beyond/compute_light_pass.hpp"

#include <string>

#include "common/barriers.hpp"
#include "common/check.hpp"
#include "common/descriptors.hpp"
#include "common/files.hpp"
#include "common/pipeline.hpp"

void writeComputeOutput(const common::Device& device, LightPass& pass) {
    // The shader writes the output through a storage-image descriptor, in GENERAL layout.
    VkDescriptorImageInfo image{.imageView = pass.output.view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                               .dstSet = pass.outputSet,
                               .dstBinding = 0,
                               .descriptorCount = 1,
                               .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                               .pImageInfo = &image};
    vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

//> compute-pipeline
// The same three sets as the fragment form plus set 3, the output as a storage image, and the
// same push constants; one shader stage, no fixed-function state.
void createComputeLightPipeline(const common::Device& device, VkPipelineCache cache, LightPass& pass,
                                const GBufferLayout& layout) {
    pass.outputLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT)});
    pass.outputSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.outputLayout);
    writeComputeOutput(device, pass);
    VkDescriptorSetLayout setLayouts[] = {pass.attachmentsLayout, pass.lightsLayout, pass.sceneLayout,
                                          pass.outputLayout, pass.tileLists};  // set 4: --light-culling tiled
    VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView)};
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                          .setLayoutCount = pass.tileLists ? 5u : 4u,
                                          .pSetLayouts = setLayouts,
                                          .pushConstantRangeCount = 1,
                                          .pPushConstantRanges = &pushRange};
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pass.computeLayout));
    VkShaderModule module =
        common::loadShaderModule(device, std::string("chapter-15/light") + layout.shaderSuffix +
                                             (pass.tileLists ? "-tiled" : "") + ".comp");
    VkComputePipelineCreateInfo pipelineInfo{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module),
        .layout = pass.computeLayout,
    };
    VK_CHECK(
        vkCreateComputePipelines(device.handle, cache, 1, &pipelineInfo, nullptr, &pass.computePipeline));
    vkDestroyShaderModule(device.handle, module, nullptr);
}
//< compute-pipeline

//> record-compute-light
// The output goes to GENERAL (a storage image), one 8x8 group per 8x8 pixels, then to READ_ONLY
// for the post pass -- the same image, the same layouts after, as the fragment form.
void recordComputeLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view,
                            VkDescriptorSet tileLists) {
    VkDescriptorSet sets[] = {pass.attachmentsSet, pass.frames[frame].lightsSet, pass.frames[frame].sceneSet,
                              pass.outputSet, tileLists};
    VkImageMemoryBarrier2 init = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.computePipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.computeLayout, 0,
                            pass.tileLists ? 5 : 4, sets, 0, nullptr);
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

void destroyComputeLightPipeline(const common::Device& device, LightPass& pass) {
    vkDestroyPipeline(device.handle, pass.computePipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.computeLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.outputLayout, nullptr);
}
