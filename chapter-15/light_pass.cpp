// chapter-15: the light pass.
#include "light_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/screenshot.hpp"
#include "common/vk/texture.hpp"

namespace {

common::Image createOutput(const common::Device& device, VkExtent2D extent, VkImageUsageFlags written) {
    // Sampled by the post pass; TRANSFER_SRC: --check-output copies it back to the CPU.
    return common::createImage(device, extent, kLightOutputFormat,
                               written | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT, "light output");
}

//> attachments-set
// One binding per colour attachment in attachment order (position, albedo, normal, pbr), then
// depth: the book's light pass samples the four colour attachments; we also read depth (--view
// depth). A layout with fewer colour attachments has fewer bindings.
void writeAttachments(const common::Device& device, LightPass& pass, const common::GBuffer& gbuffer) {
    uint32_t binding = 0;
    for (const common::Image* color : common::colorAttachments(gbuffer))
        common::writeImageDescriptor(device, pass.attachmentsSet, binding++, pass.sampler, color->view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    common::writeImageDescriptor(device, pass.attachmentsSet, binding, pass.sampler, gbuffer.depth.view,
                                 VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}
//< attachments-set

}  // namespace

//> shader-lights
std::vector<ShaderLight> shaderLights(const common::Scene& scene) {
    std::vector<ShaderLight> lights;
    for (bool directionalPass : {true, false})
        for (const common::Light& light : scene.lights) {
            bool directional = light.type == common::Light::Type::Directional;
            if (directional != directionalPass) continue;
            lights.push_back({directional ? light.direction : light.position, directional ? 1u : 0u,
                              light.intensity, light.color, directional ? 0.0f : light.range});
        }
    return lights;
}
//< shader-lights

bool inKindOrder(const std::vector<ShaderLight>& lights, LightKinds kinds) {
    if (int64_t(lights.size()) != int64_t(kinds.directional) + kinds.point) return false;
    for (size_t i = 0; i < lights.size(); ++i)
        if ((lights[i].directional != 0u) != (int64_t(i) < kinds.directional)) return false;
    return true;
}

LightKinds lightKinds(const std::vector<ShaderLight>& lights) {
    auto directional = std::count_if(lights.begin(), lights.end(),
                                     [](const ShaderLight& light) { return light.directional != 0u; });
    return {int32_t(directional), int32_t(lights.size()) - int32_t(directional)};
}

std::string describeLightKinds(LightKinds kinds) {
    if (kinds == LightKinds{}) return "generic";
    return std::to_string(kinds.directional) + " directional, " + std::to_string(kinds.point) + " point";
}

LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GBuffer& gbuffer, uint32_t framesInFlight, uint32_t lightCapacity,
                          const LightPassSetup& setup) {
    LightPass pass;
    pass.outputUsage = setup.outputUsage;
    pass.output = createOutput(device, extent, setup.outputUsage);
    VkShaderStageFlags stage = setup.stages;
    std::vector<VkDescriptorSetLayoutBinding> attachmentBindings;
    size_t colorCount = common::colorAttachments(gbuffer).size();
    for (uint32_t i = 0; i <= colorCount; ++i)  // the colour attachments, then depth
        attachmentBindings.push_back(common::binding(i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stage));
    VkDescriptorSetLayoutCreateInfo attachmentsInfo{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .bindingCount = uint32_t(attachmentBindings.size()),
        .pBindings = attachmentBindings.data()};
    VK_CHECK(vkCreateDescriptorSetLayout(device.handle, &attachmentsInfo, nullptr, &pass.attachmentsLayout));
    common::nameObject(device.handle, pass.attachmentsLayout, "light: G-buffer attachments");
    pass.lightsLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, stage)}, "light: lights");
    pass.sceneLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stage)}, "light: scene info");
    pass.descriptorPool = common::createDescriptorPool(
        device, 2 + 2 * framesInFlight,
        {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(attachmentBindings.size())},
         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, framesInFlight},
         {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight}},
        "light");
    pass.attachmentsSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.attachmentsLayout,
                                                        "light: G-buffer attachments");
    // One texel per pixel: nearest filtering, which depth formats always support.
    pass.sampler =
        common::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    writeAttachments(device, pass, gbuffer);

    //> light-buffers
    // Lights and scene info change every frame (the keys move the lights, the camera moves):
    // one host-visible buffer of each per frame in flight. The lights buffer holds exactly the
    // scene's lights (one unused element when there are none: a buffer cannot be empty). Both
    // are read with the scalar layout (the device's scalarBlockLayout feature, main.cpp).
    pass.lightCapacity = lightCapacity;
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    pass.frames.resize(framesInFlight);
    for (LightFrame& frame : pass.frames) {
        frame.lights = common::createBuffer(device, std::max(lightCapacity, 1u) * sizeof(ShaderLight),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hostVisible, "lights");
        frame.scene = common::createBuffer(device, sizeof(ShaderSceneInfo),
                                           VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, hostVisible, "scene info");
        frame.lightsSet =
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.lightsLayout, "light: lights");
        frame.sceneSet =
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.sceneLayout, "light: scene info");
        common::writeBufferDescriptor(device, frame.lightsSet, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                      frame.lights.handle, VK_WHOLE_SIZE);
        common::writeBufferDescriptor(device, frame.sceneSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      frame.scene.handle, sizeof(ShaderSceneInfo));
    }
    //< light-buffers

    pass.kinds = setup.kinds;
    if (setup.fragmentShader.empty()) return pass;
    std::vector<VkDescriptorSetLayout> sets{pass.attachmentsLayout, pass.lightsLayout, pass.sceneLayout};
    sets.insert(sets.end(), setup.moreSets.begin(), setup.moreSets.end());
    //> light-specialization
    // The pipeline for the scene's lights: their number of each kind as constants (none given:
    // the generic pipeline).
    LightConstants constants(pass.kinds);
    VkSpecializationInfo specialization = constants.info();
    pass.pipeline = common::createFullscreenPipeline(device, cache, setup.fragmentShader.c_str(),
                                                     kLightOutputFormat, sets, sizeof(LightView),
                                                     pass.kinds == LightKinds{} ? nullptr : &specialization);
    //< light-specialization
    return pass;
}

void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const common::GBuffer& gbuffer) {
    common::destroyImage(device, pass.output);
    pass.output = createOutput(device, extent, pass.outputUsage);
    writeAttachments(device, pass, gbuffer);
}

void updateLights(LightPass& pass, uint32_t frame, const std::vector<ShaderLight>& lights,
                  const ShaderSceneInfo& scene) {
    // std::copy_n, not memcpy: a scene with no lights has lights.data() == nullptr, which memcpy
    // must not be given even for 0 bytes (UndefinedBehaviorSanitizer reports it).
    if (pass.kinds != LightKinds{} && !inKindOrder(lights, pass.kinds))
        throw common::Failure("the light pass was made for " + describeLightKinds(pass.kinds) +
                              " lights, directional first; it was given " +
                              describeLightKinds(lightKinds(lights)) + " (or another order)");
    uint32_t count = std::min<uint32_t>(uint32_t(lights.size()), pass.lightCapacity);
    std::copy_n(lights.data(), count, static_cast<ShaderLight*>(pass.frames[frame].lights.mapped));
    ShaderSceneInfo info = scene;
    info.lightCount = count;
    std::memcpy(pass.frames[frame].scene.mapped, &info, sizeof(info));
}

//> record-light
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view,
                     std::span<const VkDescriptorSet> moreSets) {
    // The output to ATTACHMENT_OPTIMAL once the previous frame's post pass has sampled it, the
    // full-screen triangle into it (rendering begun as chapter-14's light pass does), and to
    // READ_ONLY_OPTIMAL for this frame's post pass.
    VkImageMemoryBarrier2 init = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    common::pipelineBarrier(cmd, &init, 1);

    common::beginFullscreen(cmd, pass.output.view, pass.output.extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.pipeline);
    VkDescriptorSet sets[] = {pass.attachmentsSet, pass.frames[frame].lightsSet, pass.frames[frame].sceneSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.layout, 0, 3, sets, 0,
                            nullptr);
    if (!moreSets.empty())
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline.layout, 3,
                                uint32_t(moreSets.size()), moreSets.data(), 0, nullptr);
    vkCmdPushConstants(cmd, pass.pipeline.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LightView), &view);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    common::vk13.CmdEndRendering(cmd);

    VkImageMemoryBarrier2 finish = common::imageBarrier(
        pass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    common::pipelineBarrier(cmd, &finish, 1);
}
//< record-light

//> check-output
// --check-output: every value of the light output must be a finite, non-negative number.
void checkLightOutput(const common::Device& device, const LightPass& pass) {
    std::vector<float> values = common::readFloatImage(device, pass.output.handle, kLightOutputFormat,
                                                       pass.output.extent, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    size_t nan = 0, infinite = 0, negative = 0;
    float largest = 0.0f;
    for (size_t i = 0; i < values.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            float v = values[i + c];
            nan += std::isnan(v);
            infinite += std::isinf(v);
            negative += v < 0.0f;
            if (std::isfinite(v)) largest = std::max(largest, v);
        }
    std::printf("light output %ux%u: %zu NaN, %zu infinite, %zu negative; largest value %g\n",
                pass.output.extent.width, pass.output.extent.height, nan, infinite, negative, largest);
    if (nan + infinite + negative != 0)
        throw common::Failure("the light output has NaN, infinite or negative values");
}
//< check-output

void destroyLightPass(const common::Device& device, LightPass& pass) {
    common::destroyFullscreenPipeline(device, pass.pipeline);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    for (LightFrame& frame : pass.frames) {
        common::destroyBuffer(device, frame.scene);
        common::destroyBuffer(device, frame.lights);
    }
    vkDestroyDescriptorSetLayout(device.handle, pass.sceneLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.lightsLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.attachmentsLayout, nullptr);
    common::destroyImage(device, pass.output);
    pass = {};
}
