// chapter-14: the scene pass.
#include "scene_pass.hpp"

#include <cstring>

#include "common/barriers.hpp"
#include "common/check.hpp"
#include "common/descriptors.hpp"
#include "common/files.hpp"
#include "common/pipeline.hpp"
#include "common/texture.hpp"

namespace {

struct CameraUniform {
    glm::mat4 projection;
    glm::mat4 view;
};

void createDescriptors(const common::Device& device, ScenePass& pass, const common::GpuScene& scene,
                       uint32_t framesInFlight) {
    pass.cameraLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)});
    pass.materialsLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)});
    pass.textureLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)});
    uint32_t textures = uint32_t(scene.textures.size());
    pass.descriptorPool =
        common::createDescriptorPool(device, framesInFlight + 1 + textures,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textures}});

    for (uint32_t i = 0; i < framesInFlight; ++i) {
        pass.cameras.push_back(
            common::createBuffer(device, sizeof(CameraUniform), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT));
        pass.cameraSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.cameraLayout));
        common::writeBufferDescriptor(device, pass.cameraSets.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      pass.cameras.back().handle, sizeof(CameraUniform));
    }

    // The materials never change: one device-local storage buffer, filled through staging.
    std::vector<glm::vec4> diffuse;
    for (const common::GpuMaterial& material : scene.materials) diffuse.push_back(material.diffuse);
    common::StagingBatch batch = common::beginStaging(device);
    pass.materials = common::uploadStaged(device, batch, diffuse.data(), diffuse.size() * sizeof(glm::vec4),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    common::endStaging(device, batch);
    pass.materialsSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.materialsLayout);
    common::writeBufferDescriptor(device, pass.materialsSet, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                  pass.materials.handle, VK_WHOLE_SIZE);

    pass.sampler = common::createSampler(device, VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_LOD_CLAMP_NONE);
    for (const common::Image& texture : scene.textures) {
        pass.textureSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.textureLayout));
        common::writeImageDescriptor(device, pass.textureSets.back(), 0, pass.sampler, texture.view,
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
}

//> scene-pipeline
void createPipeline(const common::Device& device, VkPipelineCache cache, ScenePass& pass) {
    std::array<VkDescriptorSetLayout, 3> layouts{pass.cameraLayout, pass.materialsLayout, pass.textureLayout};
    std::array<VkPushConstantRange, 2> pushConstants{{
        {.stageFlags = VK_SHADER_STAGE_VERTEX_BIT, .offset = 0, .size = sizeof(glm::mat4)},  // model matrix
        {.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT,
         .offset = sizeof(glm::mat4),
         .size = sizeof(uint32_t)},  // material
    }};
    VkPipelineLayoutCreateInfo layoutInfo{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = uint32_t(layouts.size()),
        .pSetLayouts = layouts.data(),
        .pushConstantRangeCount = uint32_t(pushConstants.size()),
        .pPushConstantRanges = pushConstants.data(),
    };
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pass.pipelineLayout));

    // Without a render pass, the pipeline is told the formats it will render to: one per colour
    // attachment (each gets its own blend state), plus depth.
    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = uint32_t(kGBufferColorFormats.size()),
        .pColorAttachmentFormats = kGBufferColorFormats.data(),
        .depthAttachmentFormat = kDepthFormat,
    };
    VkShaderModule vertex = common::loadShaderModule(device, "chapter-14/scene.vert");
    VkShaderModule fragment = common::loadShaderModule(device, "chapter-14/scene.frag");
    common::SceneVertexInput vertexInput;
    common::describeSceneVertexInput(vertexInput, common::kPosition | common::kUv);
    pass.pipeline = common::createGraphicsPipeline(
        device, cache,
        {
            .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                       common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment)},
            .vertexInput = &vertexInput.state,
            .depthTest = true,
            .depthWrite = true,
            .colorAttachmentCount = uint32_t(kGBufferColorFormats.size()),
            .layout = pass.pipelineLayout,
            .renderPass = VK_NULL_HANDLE,
            .pNext = &rendering,
        });
    vkDestroyShaderModule(device.handle, fragment, nullptr);
    vkDestroyShaderModule(device.handle, vertex, nullptr);
}
//< scene-pipeline

}  // namespace

ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight) {
    ScenePass pass;
    pass.gbuffer = common::createGBuffer(device, extent, kGBufferColorFormats, kDepthFormat);
    createDescriptors(device, pass, scene, framesInFlight);
    createPipeline(device, cache, pass);
    return pass;
}

void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent) {
    common::destroyGBuffer(device, pass.gbuffer);
    pass.gbuffer = common::createGBuffer(device, extent, kGBufferColorFormats, kDepthFormat);
}

void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view) {
    CameraUniform camera{projection, view};
    std::memcpy(pass.cameras[frame].mapped, &camera, sizeof(camera));
}

//> record-scene
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame) {
    // renderInit: the attachments to ATTACHMENT_OPTIMAL, then rendering begins on them.
    common::gbufferRenderInit(cmd, pass.gbuffer);
    common::beginGBufferRendering(cmd, pass.gbuffer);
    VkExtent2D extent = pass.gbuffer.depth.extent;

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    std::array<VkDescriptorSet, 2> shared{pass.cameraSets[frame], pass.materialsSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 2, shared.data(), 0,
                            nullptr);
    for (const common::Draw& draw : scene.draws) {
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &mesh.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 2, 1,
                                &pass.textureSets[scene.materials[draw.material].albedoTexture], 0, nullptr);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &draw.model);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_FRAGMENT_BIT, sizeof(glm::mat4),
                           sizeof(uint32_t), &draw.material);
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, 0, 0, 0);
    }

    vkCmdEndRendering(cmd);
    common::gbufferRenderFinish(cmd, pass.gbuffer);  // renderFinish: to READ_ONLY_OPTIMAL for the light pass
}
//< record-scene

void destroyScenePass(const common::Device& device, ScenePass& pass) {
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    common::destroyBuffer(device, pass.materials);
    for (common::Buffer& camera : pass.cameras) common::destroyBuffer(device, camera);
    vkDestroyDescriptorSetLayout(device.handle, pass.textureLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.materialsLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.cameraLayout, nullptr);
    common::destroyGBuffer(device, pass.gbuffer);
    pass = {};
}
