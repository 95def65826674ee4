// chapter-14: the scene pass.
#include "scene_pass.hpp"

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

//> create-gbuffer
// The attachments are written by this pass (COLOR_ATTACHMENT, DEPTH_STENCIL_ATTACHMENT) and
// sampled by the light pass (SAMPLED).
GBuffer createGBuffer(const common::Device& device, VkExtent2D extent, VkFormat depthFormat) {
    return {
        .albedo = common::createImage(device, extent, kAlbedoFormat,
                                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                      VK_IMAGE_ASPECT_COLOR_BIT, "G-buffer albedo"),
        .depth = common::createImage(device, extent, depthFormat,
                                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                     VK_IMAGE_ASPECT_DEPTH_BIT, "G-buffer depth"),
    };
}
//< create-gbuffer

void destroyGBuffer(const common::Device& device, GBuffer& gbuffer) {
    common::destroyImage(device, gbuffer.depth);
    common::destroyImage(device, gbuffer.albedo);
}

void createDescriptors(const common::Device& device, ScenePass& pass, const common::GpuScene& scene,
                       uint32_t framesInFlight) {
    pass.cameraLayout = common::createCameraSetLayout(device);
    pass.materialsLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "scene: materials");
    pass.textureLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "scene: texture");
    uint32_t materials = uint32_t(scene.materials.size());
    pass.descriptorPool =
        common::createDescriptorPool(device, framesInFlight + 1 + materials,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, materials}},
                                     "scene");

    pass.cameras = common::createCameraFrames(device, pass.descriptorPool, pass.cameraLayout, framesInFlight);

    // The materials never change: one device-local storage buffer, filled through staging.
    std::vector<SceneMaterial> materialData;
    for (const common::GpuMaterial& material : scene.materials)
        materialData.push_back({material.diffuse, material.alphaTested ? material.alphaCutoff : 0.0f, {}});
    common::StagingBatch batch = common::beginStaging(device);
    pass.materials =
        common::uploadStaged(device, batch, materialData.data(), materialData.size() * sizeof(SceneMaterial),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");
    common::endStaging(device, batch);
    pass.materialsSet =
        common::allocateDescriptorSet(device, pass.descriptorPool, pass.materialsLayout, "scene: materials");
    common::writeBufferDescriptor(device, pass.materialsSet, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                  pass.materials.handle, VK_WHOLE_SIZE);

    // A set per material: its albedo texture with the sampler the model gives it.
    for (const common::GpuMaterial& material : scene.materials) {
        pass.textureSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.textureLayout, "scene: texture"));
        common::writeImageDescriptor(
            device, pass.textureSets.back(), 0, scene.samplers[material.albedo.sampler],
            scene.textures[material.albedo.image].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
}

//> scene-pipeline
const std::vector<std::string> kSceneShaders{"chapter-14/scene.vert", "chapter-14/scene.frag"};

// A class's pipeline from the shaders' current code: at start-up, and again on a live reload.
VkPipeline makePipeline(const common::Device& device, VkPipelineCache cache, const ScenePass& pass,
                        const MaterialClass& materialClass) {
    // Without a render pass, the pipeline is told the formats it will render to: one per colour
    // attachment (each gets its own blend state), plus depth.
    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = 1,
        .pColorAttachmentFormats = &kAlbedoFormat,
        .depthAttachmentFormat = pass.gbuffer.depth.format,
    };
    common::ShaderModule vertex(device, kSceneShaders[0]);
    common::ShaderModule fragment(device, kSceneShaders[1]);
    common::SceneVertexInput vertexInput;
    common::describeSceneVertexInput(vertexInput, common::kPosition | common::kUv);
    // The class's two constants, constant_id 0 and 1 of scene.frag (as chapter-06 sets its one).
    std::array<VkBool32, 2> constants{materialClass.alphaTest, materialClass.baseColorMap};
    std::array<VkSpecializationMapEntry, 2> entries{{{0, 0, sizeof(VkBool32)}, {1, 4, sizeof(VkBool32)}}};
    VkSpecializationInfo specialization{.mapEntryCount = uint32_t(entries.size()),
                                        .pMapEntries = entries.data(),
                                        .dataSize = sizeof(constants),
                                        .pData = constants.data()};
    std::string name = std::string("scene: ") + (materialClass.alphaTest ? "cut-out" : "opaque") +
                       (materialClass.baseColorMap ? ", texture" : "");
    return common::createGraphicsPipeline(
        device, cache,
        {
            .name = name,
            .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                       common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment, &specialization)},
            .vertexInput = &vertexInput.state,
            .depthTest = true,
            .depthWrite = true,
            .colorAttachmentCount = 1,
            .layout = pass.pipelineLayout,
            .renderPass = VK_NULL_HANDLE,
            .pNext = &rendering,
        });
}

void createPipelines(const common::Device& device, VkPipelineCache cache, ScenePass& pass,
                     const common::GpuScene& scene, bool generic) {
    std::array<VkDescriptorSetLayout, 3> layouts{pass.cameraLayout, pass.materialsLayout, pass.textureLayout};
    std::array<VkPushConstantRange, 2> pushConstants{{
        {.stageFlags = VK_SHADER_STAGE_VERTEX_BIT, .offset = 0, .size = sizeof(glm::mat4)},  // model matrix
        {.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT,
         .offset = sizeof(glm::mat4),
         .size = sizeof(uint32_t)},  // material
    }};
    pass.pipelineLayout = common::createPipelineLayout(device, layouts, pushConstants, "scene");

    // The material classes the scene has: a cut-out is a material whose alpha is tested; one
    // without a texture samples none. Generic: one class, both on, right for every material.
    std::vector<bool> used = common::usedMaterials(scene);  // a material no draw uses adds no class
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const common::GpuMaterial& material = scene.materials[i];
        pass.materialClasses.add(
            generic ? MaterialClass{}
                    : MaterialClass{material.alphaTested, material.albedo.image != common::kWhiteTexture},
            used[i]);
    }
    for (const MaterialClass& materialClass : pass.materialClasses.classes)
        pass.pipelines.push_back(makePipeline(device, cache, pass, materialClass));
}
//< scene-pipeline

//> render-init
// The book's renderInit: every attachment to ATTACHMENT_OPTIMAL before drawing. The old contents
// are cleared, so the old layout is UNDEFINED; but the previous frame's light pass may still be
// sampling them in its fragment shader, so the transition waits for that stage (a write after a
// read needs only this execution dependency: no access to make available).
void renderInit(VkCommandBuffer cmd, const GBuffer& gbuffer) {
    VkImageMemoryBarrier2 barriers[] = {
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            .srcAccessMask = VK_ACCESS_2_NONE,
            .dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            .dstAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .newLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = gbuffer.albedo.handle,
            .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},
        },
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            .srcAccessMask = VK_ACCESS_2_NONE,
            // The depth test reads and writes depth in both fragment-test stages.
            .dstStageMask =
                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            .dstAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .newLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = gbuffer.depth.handle,
            .subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1},
        },
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 2,
        .pImageMemoryBarriers = barriers,
    };
    common::vk13.CmdPipelineBarrier2(cmd, &dependency);
}
//< render-init

//> render-finish
// The book's renderFinish: every attachment to READ_ONLY_OPTIMAL after drawing, its writes made
// available and visible to the light pass's fragment shader (a read after a write).
void renderFinish(VkCommandBuffer cmd, const GBuffer& gbuffer) {
    VkImageMemoryBarrier2 barriers[] = {
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            .srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            .dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .newLayout = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = gbuffer.albedo.handle,
            .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},
        },
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,  // where the last depth write is
            .srcAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            .dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .newLayout = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = gbuffer.depth.handle,
            .subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1},
        },
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 2,
        .pImageMemoryBarriers = barriers,
    };
    common::vk13.CmdPipelineBarrier2(cmd, &dependency);
}
//< render-finish

//> begin-rendering
// What a framebuffer and the render pass's attachment descriptions used to say, now given when
// rendering begins: the image view of each attachment, its layout, and what happens to its
// contents at the start (cleared) and at the end (stored: the light pass reads them).
void beginRendering(VkCommandBuffer cmd, const GBuffer& gbuffer) {
    VkRenderingAttachmentInfo albedo{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = gbuffer.albedo.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}},  // alpha 0: no surface here
    };
    VkRenderingAttachmentInfo depth{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = gbuffer.depth.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,  // the light pass shows it (--view depth)
        .clearValue = {.depthStencil = {1.0f, 0}},
    };
    VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, gbuffer.depth.extent},
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &albedo,
        .pDepthAttachment = &depth,
    };
    common::vk13.CmdBeginRendering(cmd, &rendering);
}
//< begin-rendering

}  // namespace

ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight, bool generic) {
    ScenePass pass;
    pass.gbuffer = createGBuffer(device, extent, common::chooseDepthFormat(device));
    createDescriptors(device, pass, scene, framesInFlight);
    createPipelines(device, cache, pass, scene, generic);
    return pass;
}

void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent) {
    VkFormat depthFormat = pass.gbuffer.depth.format;
    destroyGBuffer(device, pass.gbuffer);
    pass.gbuffer = createGBuffer(device, extent, depthFormat);
}

void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view) {
    common::writeCamera(pass.cameras[frame], projection, view);
}

//> record-scene
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame) {
    renderInit(cmd, pass.gbuffer);
    beginRendering(cmd, pass.gbuffer);
    VkExtent2D extent = pass.gbuffer.depth.extent;

    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    std::array<VkDescriptorSet, 2> shared{pass.cameras[frame].set, pass.materialsSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 2, shared.data(), 0,
                            nullptr);
    VkPipeline bound = VK_NULL_HANDLE;
    for (const common::Draw& draw : scene.draws) {
        // The pipeline of the draw's material class, bound when it differs from the last draw's.
        VkPipeline pipeline = pass.pipelines[pass.materialClasses.ofMaterial[draw.material]];
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &mesh.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 2, 1,
                                &pass.textureSets[draw.material], 0, nullptr);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &draw.model);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_FRAGMENT_BIT, sizeof(glm::mat4),
                           sizeof(uint32_t), &draw.material);
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, 0, 0, 0);
    }

    common::vk13.CmdEndRendering(cmd);
    renderFinish(cmd, pass.gbuffer);
}
//< record-scene

void remakeScenePipeline(const common::Device& device, VkPipelineCache cache, ScenePass& pass,
                         const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (reload.changed(kSceneShaders))
        for (size_t i = 0; i < pass.pipelines.size(); ++i)
            common::replacePipeline(swap, pass.pipelines[i], [&] {
                return makePipeline(device, cache, pass, pass.materialClasses.classes[i]);
            });
}

void destroyScenePass(const common::Device& device, ScenePass& pass) {
    for (VkPipeline pipeline : pass.pipelines) vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    common::destroyBuffer(device, pass.materials);
    common::destroyCameraFrames(device, pass.cameras);
    vkDestroyDescriptorSetLayout(device.handle, pass.textureLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.materialsLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.cameraLayout, nullptr);
    destroyGBuffer(device, pass.gbuffer);
    pass = {};
}
