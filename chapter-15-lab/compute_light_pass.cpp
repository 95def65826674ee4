// chapter-15-lab: the compute light pass.
#include "compute_light_pass.hpp"

#include <string>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/pipeline.hpp"

LightPassSetup computeLightPassSetup(VkShaderStageFlags alsoStages) {
    return {.fragmentShader = "",
            .stages = VK_SHADER_STAGE_COMPUTE_BIT | alsoStages,
            .outputUsage = VK_IMAGE_USAGE_STORAGE_BIT};
}

void writeComputeOutput(const common::Device& device, const ComputeLightPass& pass,
                        const LightPass& lightPass) {
    // The shader writes the output through a storage-image descriptor, in GENERAL layout.
    VkDescriptorImageInfo image{.imageView = lightPass.output.view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                               .dstSet = pass.outputSet,
                               .dstBinding = 0,
                               .descriptorCount = 1,
                               .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                               .pImageInfo = &image};
    vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

namespace {

// The pipeline from the shader's current code: at start-up, and again on a live reload.
VkPipeline makePipeline(const common::Device& device, VkPipelineCache cache, const ComputeLightPass& pass) {
    common::ShaderModule module(device, pass.shader);
    LightConstants constants(pass.kinds);  // the light pass's specialisation (light_loop.glsl)
    VkSpecializationInfo specialization = constants.info();
    VkComputePipelineCreateInfo pipelineInfo{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module,
                                     pass.kinds == LightKinds{} ? nullptr : &specialization),
        .layout = pass.pipelineLayout,
    };
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device.handle, cache, 1, &pipelineInfo, nullptr, &pipeline));
    common::nameObject(device.handle, pipeline, pass.shader);
    return pipeline;
}

}  // namespace

void remakeComputeLightPipeline(const common::Device& device, VkPipelineCache cache, ComputeLightPass& pass,
                                const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (pass.pipeline == VK_NULL_HANDLE || !reload.changed({pass.shader})) return;
    common::replacePipeline(swap, pass.pipeline, [&] { return makePipeline(device, cache, pass); });
}

//> compute-pipeline
// The same three sets as the fragment form plus set 3, the output as a storage image, and the
// same push constants; one shader stage, no fixed-function state.
ComputeLightPass createComputeLightPass(const common::Device& device, VkPipelineCache cache,
                                        const LightPass& lightPass, const std::string& shader,
                                        VkDescriptorSetLayout tileLists) {
    ComputeLightPass pass;
    pass.tiled = tileLists != VK_NULL_HANDLE;
    pass.outputLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT)},
        "compute light: output");
    pass.descriptorPool =
        common::createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}}, "compute light");
    pass.outputSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.outputLayout,
                                                   "compute light: output");
    writeComputeOutput(device, pass, lightPass);
    VkDescriptorSetLayout setLayouts[] = {lightPass.attachmentsLayout, lightPass.lightsLayout,
                                          lightPass.sceneLayout, pass.outputLayout,
                                          tileLists};  // set 4: --light-culling tiled
    VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView)};
    pass.pipelineLayout = common::createPipelineLayout(device, {setLayouts, pass.tiled ? 5u : 4u},
                                                       {&pushRange, 1}, "compute light");
    pass.shader = shader;
    pass.kinds = lightPass.kinds;
    pass.pipeline = makePipeline(device, cache, pass);
    return pass;
}
//< compute-pipeline

//> record-compute-light
// The output goes to GENERAL (a storage image), one 8x8 group per 8x8 pixels, then to READ_ONLY
// for the post pass -- the same image, the same layouts after, as the fragment form.
void recordComputeLightPass(VkCommandBuffer cmd, const ComputeLightPass& pass, const LightPass& lightPass,
                            uint32_t frame, const LightView& view, VkDescriptorSet tileLists) {
    VkDescriptorSet sets[] = {lightPass.attachmentsSet, lightPass.frames[frame].lightsSet,
                              lightPass.frames[frame].sceneSet, pass.outputSet, tileLists};
    VkImageMemoryBarrier2 init = common::imageBarrier(
        lightPass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipelineLayout, 0, pass.tiled ? 5 : 4,
                            sets, 0, nullptr);
    vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView), &view);
    VkExtent2D extent = lightPass.output.extent;
    vkCmdDispatch(cmd, (extent.width + 7) / 8, (extent.height + 7) / 8, 1);

    VkImageMemoryBarrier2 finish =
        common::imageBarrier(lightPass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                             VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    common::pipelineBarrier(cmd, &finish, 1);
}
//< record-compute-light

void destroyComputeLightPass(const common::Device& device, ComputeLightPass& pass) {
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.outputLayout, nullptr);
    pass = {};
}
