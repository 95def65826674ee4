// chapter-15-lab: forward shading, the renderer deferred shading is measured against.
#include "forward_shading.hpp"

#include <array>

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"

Shading readShading(const common::Options& options) {
    auto given = options.choices.find("shading");
    if (given == options.choices.end() || given->second == 0) return Shading::Deferred;
    auto chosen = [&](const char* name) {
        auto found = options.choices.find(name);
        return found == options.choices.end() ? 0u : found->second;
    };
    if (chosen("light-pass") != 0)
        throw common::InputError("--light-pass compute shades the G-buffer: --shading forward has none");
    if (chosen("light-culling") != 0)
        throw common::InputError(
            "--light-culling tiled bounds its tiles with the G-buffer's depth: --shading forward has no "
            "light culling");
    if (chosen("gbuffer") != 0)
        throw common::InputError("--shading forward has no G-buffer to lay out (--gbuffer)");
    if (options.view != 0)
        throw common::InputError(
            "--view shows the G-buffer's attachments: --shading forward has only the final image");
    return Shading::Forward;
}

ForwardPass createForwardPass(const common::Device& device, VkPipelineCache cache, const ScenePass& scenePass,
                              const LightPass& lightPass) {
    ForwardPass pass;
    pass.pipelines = createScenePipelines(
        device, cache, scenePass,
        {.shaders = {.vertex = "chapter-15-lab/scene.vert", .fragment = "chapter-15-lab/forward.frag"},
         .colorFormats = {kLightOutputFormat},
         .depthFormat = scenePass.formats.depth,
         .reversedZ = scenePass.layout->reversedZ,
         .moreSets = {lightPass.lightsLayout, lightPass.sceneLayout}});
    return pass;
}

//> record-forward
void recordForwardPass(VkCommandBuffer cmd, const ForwardPass& pass, ScenePass& scenePass,
                       const LightPass& lightPass, const common::GpuScene& scene, uint32_t frame,
                       glm::vec3 cameraPosition) {
    // The light output and depth to ATTACHMENT_OPTIMAL once the previous frame has read them (the
    // post pass samples the output), their old contents dropped.
    const common::Image& depth = scenePass.gbuffer.depth;
    std::array<VkImageMemoryBarrier2, 2> init{
        common::imageBarrier(lightPass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                             VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT),
        common::imageBarrier(
            depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_NONE,
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
    common::pipelineBarrier(cmd, init.data(), uint32_t(init.size()));

    // One colour attachment, cleared to the light pass's colour where no surface is; depth cleared
    // to the far plane.
    VkRenderingAttachmentInfo color{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = lightPass.output.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 1.0f}}},
    };
    VkRenderingAttachmentInfo depthAttachment{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = depth.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue = {.depthStencil = {scenePass.layout->reversedZ ? 0.0f : 1.0f, 0}},
    };
    VkExtent2D extent = lightPass.output.extent;
    VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, extent},
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &color,
        .pDepthAttachment = &depthAttachment,
    };
    common::vk13.CmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    // Sets 0 and 1 as the scene pass binds them, 3 and 4 the light pass's; set 2 per draw.
    std::array<VkDescriptorSet, 2> shared{scenePass.cameras[frame].set, scenePass.materialsSet};
    std::array<VkDescriptorSet, 2> lights{lightPass.frames[frame].lightsSet,
                                          lightPass.frames[frame].sceneSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelines.layout, 0, 2, shared.data(),
                            0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelines.layout, 3, 2, lights.data(),
                            0, nullptr);
    recordSceneDraws(cmd, scenePass, pass.pipelines, scene, cameraPosition);
    common::vk13.CmdEndRendering(cmd);

    std::array<VkImageMemoryBarrier2, 2> finish{
        common::imageBarrier(lightPass.output.handle, VK_IMAGE_ASPECT_COLOR_BIT,
                             VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                             VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT),
        common::imageBarrier(depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                             VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_NONE)};
    common::pipelineBarrier(cmd, finish.data(), uint32_t(finish.size()));
}
//< record-forward

void destroyForwardPass(const common::Device& device, ForwardPass& pass) {
    destroyScenePipelines(device, pass.pipelines);
}
