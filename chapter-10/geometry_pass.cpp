// chapter-10: the geometry pass.
#include "geometry_pass.hpp"

#include <array>
#include <cstring>
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

constexpr VkFormat kAlbedoFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

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

//> geometry-render-pass
VkRenderPass createGeometryRenderPass(const common::Device& device, VkFormat depthFormat) {
    // Both attachments are cleared, kept for the lighting pass, and end in the layouts it
    // samples them in, so the render pass itself does the transition.
    std::array<VkAttachmentDescription, 2> attachments{{
        {
            .format = kAlbedoFormat,
            .samples = VK_SAMPLE_COUNT_1_BIT,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
            .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
        },
        {
            .format = depthFormat,
            .samples = VK_SAMPLE_COUNT_1_BIT,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
            .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
        },
    }};
    VkAttachmentReference albedoRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{
        .pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
        .colorAttachmentCount = 1,
        .pColorAttachments = &albedoRef,
        .pDepthStencilAttachment = &depthRef,
    };

    std::array<VkSubpassDependency, 2> dependencies{{
        // The previous frame's lighting pass samples these attachments in its fragment shader.
        // Our clear and layout transition (a write) must wait for those reads to finish:
        // a write-after-read hazard, for which an execution dependency is enough.
        {
            .srcSubpass = VK_SUBPASS_EXTERNAL,
            .dstSubpass = 0,
            .srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                            VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
            .srcAccessMask = 0,
            .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
        },
        // Our colour and depth writes, and the final layout transition, must be done and
        // visible before the lighting pass samples them: a read-after-write hazard.
        {
            .srcSubpass = 0,
            .dstSubpass = VK_SUBPASS_EXTERNAL,
            .srcStageMask =
                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            .srcAccessMask =
                VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            .dstAccessMask = VK_ACCESS_SHADER_READ_BIT,
        },
    }};
    VkRenderPassCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
        .attachmentCount = uint32_t(attachments.size()),
        .pAttachments = attachments.data(),
        .subpassCount = 1,
        .pSubpasses = &subpass,
        .dependencyCount = uint32_t(dependencies.size()),
        .pDependencies = dependencies.data(),
    };
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(device.handle, &info, nullptr, &renderPass));
    common::nameObject(device.handle, renderPass, "geometry");
    return renderPass;
}
//< geometry-render-pass

VkFramebuffer createGeometryFramebuffer(const common::Device& device, VkRenderPass renderPass,
                                        const GBuffer& gbuffer) {
    std::array<VkImageView, 2> views{gbuffer.albedo.view, gbuffer.depth.view};
    VkFramebufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
        .renderPass = renderPass,
        .attachmentCount = uint32_t(views.size()),
        .pAttachments = views.data(),
        .width = gbuffer.albedo.extent.width,
        .height = gbuffer.albedo.extent.height,
        .layers = 1,
    };
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(device.handle, &info, nullptr, &framebuffer));
    common::nameObject(device.handle, framebuffer, "G-buffer");
    return framebuffer;
}

void createDescriptors(const common::Device& device, GeometryPass& pass, const common::GpuScene& scene,
                       uint32_t framesInFlight) {
    pass.matrixLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)},
        "geometry: matrix");
    pass.textureLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "geometry: texture");
    pass.materialLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "geometry: material");

    //> descriptor-pool
    // Sized from what the scene holds: a set per material, a view matrix per frame in flight.
    uint32_t textures = uint32_t(scene.materials.size());
    pass.descriptorPool =
        common::createDescriptorPool(device, 2 + framesInFlight + textures,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1 + framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textures},
                                      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1}},
                                     "geometry");
    //< descriptor-pool

    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    pass.projection = common::createBuffer(device, sizeof(glm::mat4), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           hostVisible, "geometry: projection");
    pass.projectionSet =
        common::allocateDescriptorSet(device, pass.descriptorPool, pass.matrixLayout, "geometry: projection");
    common::writeBufferDescriptor(device, pass.projectionSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                  pass.projection.handle, sizeof(glm::mat4));
    // One view matrix per frame in flight: the CPU writes frame N+1's while the GPU may still
    // read frame N's.
    pass.views.resize(framesInFlight);
    for (ViewFrame& view : pass.views) {
        view.buffer = common::createBuffer(device, sizeof(glm::mat4), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           hostVisible, "geometry: view");
        view.set =
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.matrixLayout, "geometry: view");
        common::writeBufferDescriptor(device, view.set, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      view.buffer.handle, sizeof(glm::mat4));
    }

    // A set per material: its albedo texture, with the sampler its model gives it.
    for (const common::GpuMaterial& material : scene.materials) {
        pass.textureSets.push_back(common::allocateDescriptorSet(device, pass.descriptorPool,
                                                                 pass.textureLayout, "geometry: texture"));
        common::writeImageDescriptor(
            device, pass.textureSets.back(), 0, scene.samplers[material.albedo.sampler],
            scene.textures[material.albedo.image].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }

    //> materials
    // Every material in one uniform buffer; a draw selects its own with a dynamic offset, which
    // must be a multiple of minUniformBufferOffsetAlignment.
    VkDeviceSize alignment = device.properties.limits.minUniformBufferOffsetAlignment;
    pass.materialStride = (sizeof(GeometryMaterial) + alignment - 1) / alignment * alignment;
    pass.materials =
        common::createBuffer(device, pass.materialStride * scene.materials.size(),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, hostVisible, "geometry: materials");
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const common::GpuMaterial& m = scene.materials[i];
        GeometryMaterial material{m.diffuse, m.alphaTested ? m.alphaCutoff : 0.0f, {}};
        std::memcpy(static_cast<char*>(pass.materials.mapped) + i * pass.materialStride, &material,
                    sizeof(material));
    }
    pass.materialSet =
        common::allocateDescriptorSet(device, pass.descriptorPool, pass.materialLayout, "geometry: material");
    common::writeBufferDescriptor(device, pass.materialSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                                  pass.materials.handle, sizeof(GeometryMaterial));
    //< materials
}

const std::vector<std::string> kGeometryShaders{"chapter-10/geometry.vert", "chapter-10/geometry.frag"};

// A class's pipeline from the shaders' current code: at start-up, and again on a live reload.
VkPipeline makePipeline(const common::Device& device, VkPipelineCache cache, const GeometryPass& pass,
                        const MaterialClass& materialClass) {
    common::ShaderModule vertex(device, kGeometryShaders[0]);
    common::ShaderModule fragment(device, kGeometryShaders[1]);
    common::SceneVertexInput vertexInput;
    common::describeSceneVertexInput(vertexInput,
                                     common::kPosition | common::kUv);  // all geometry.vert reads
    //> class-constants
    // The class's two constants, constant_id 0 and 1 of geometry.frag (as chapter-06 sets its one).
    std::array<VkBool32, 2> constants{materialClass.alphaTest, materialClass.baseColorMap};
    std::array<VkSpecializationMapEntry, 2> entries{{{0, 0, sizeof(VkBool32)}, {1, 4, sizeof(VkBool32)}}};
    VkSpecializationInfo specialization{.mapEntryCount = uint32_t(entries.size()),
                                        .pMapEntries = entries.data(),
                                        .dataSize = sizeof(constants),
                                        .pData = constants.data()};
    //< class-constants
    std::string name = std::string("geometry: ") + (materialClass.alphaTest ? "cut-out" : "opaque") +
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
            .renderPass = pass.renderPass,
        });
}

void createPipelines(const common::Device& device, VkPipelineCache cache, GeometryPass& pass,
                     const common::GpuScene& scene, bool generic) {
    std::array<VkDescriptorSetLayout, 4> layouts{pass.matrixLayout, pass.matrixLayout, pass.textureLayout,
                                                 pass.materialLayout};
    VkPushConstantRange modelMatrix{
        .stageFlags = VK_SHADER_STAGE_VERTEX_BIT, .offset = 0, .size = sizeof(glm::mat4)};
    VkPipelineLayoutCreateInfo layoutInfo{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = uint32_t(layouts.size()),
        .pSetLayouts = layouts.data(),
        .pushConstantRangeCount = 1,
        .pPushConstantRanges = &modelMatrix,
    };
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pass.pipelineLayout));
    common::nameObject(device.handle, pass.pipelineLayout, "geometry");

    //> material-classes
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
    //< material-classes
}

}  // namespace

GeometryPass createGeometryPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                                const common::GpuScene& scene, uint32_t framesInFlight, bool generic) {
    GeometryPass pass;
    // D32_SFLOAT where the device has it, else a 24-bit depth format (common/vk/formats.hpp).
    pass.depthFormat = common::chooseDepthFormat(device);
    pass.renderPass = createGeometryRenderPass(device, pass.depthFormat);
    pass.gbuffer = createGBuffer(device, extent, pass.depthFormat);
    pass.framebuffer = createGeometryFramebuffer(device, pass.renderPass, pass.gbuffer);
    createDescriptors(device, pass, scene, framesInFlight);
    createPipelines(device, cache, pass, scene, generic);
    return pass;
}

void resizeGeometryPass(const common::Device& device, GeometryPass& pass, VkExtent2D extent) {
    vkDestroyFramebuffer(device.handle, pass.framebuffer, nullptr);
    common::destroyImage(device, pass.gbuffer.depth);
    common::destroyImage(device, pass.gbuffer.albedo);
    pass.gbuffer = createGBuffer(device, extent, pass.depthFormat);
    pass.framebuffer = createGeometryFramebuffer(device, pass.renderPass, pass.gbuffer);
}

void setProjection(GeometryPass& pass, const glm::mat4& projection) {
    std::memcpy(pass.projection.mapped, &projection, sizeof(projection));
}

void setView(GeometryPass& pass, uint32_t frame, const glm::mat4& view) {
    std::memcpy(pass.views[frame].buffer.mapped, &view, sizeof(view));
}

//> record-geometry
void recordGeometryPass(VkCommandBuffer cmd, const GeometryPass& pass, const common::GpuScene& scene,
                        uint32_t frame) {
    VkExtent2D extent = pass.gbuffer.albedo.extent;
    std::array<VkClearValue, 2> clears{};
    clears[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
        .renderPass = pass.renderPass,
        .framebuffer = pass.framebuffer,
        .renderArea = {{0, 0}, extent},
        .clearValueCount = uint32_t(clears.size()),
        .pClearValues = clears.data(),
    };
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);

    // Sets 0 and 1 are the same for every draw; 2 and 3 change with the material.
    std::array<VkDescriptorSet, 2> matrices{pass.projectionSet, pass.views[frame].set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 2, matrices.data(),
                            0, nullptr);
    VkPipeline bound = VK_NULL_HANDLE;
    for (const common::Draw& draw : scene.draws) {
        // The pipeline of the draw's material class, bound when it differs from the last draw's.
        VkPipeline pipeline = pass.pipelines[pass.materialClasses.ofMaterial[draw.material]];
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &mesh.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        std::array<VkDescriptorSet, 2> materialSets{pass.textureSets[draw.material], pass.materialSet};
        uint32_t materialOffset = uint32_t(draw.material * pass.materialStride);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 2, 2,
                                materialSets.data(), 1, &materialOffset);
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &draw.model);
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, 0, 0, 0);
    }
    vkCmdEndRenderPass(cmd);
}
//< record-geometry

void remakeGeometryPipeline(const common::Device& device, VkPipelineCache cache, GeometryPass& pass,
                            const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (reload.changed(kGeometryShaders))
        for (size_t i = 0; i < pass.pipelines.size(); ++i)
            common::replacePipeline(swap, pass.pipelines[i], [&] {
                return makePipeline(device, cache, pass, pass.materialClasses.classes[i]);
            });
}

void destroyGeometryPass(const common::Device& device, GeometryPass& pass) {
    for (VkPipeline pipeline : pass.pipelines) vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);  // frees its sets
    common::destroyBuffer(device, pass.materials);
    for (ViewFrame& view : pass.views) common::destroyBuffer(device, view.buffer);
    common::destroyBuffer(device, pass.projection);
    vkDestroyDescriptorSetLayout(device.handle, pass.materialLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.textureLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.matrixLayout, nullptr);
    vkDestroyFramebuffer(device.handle, pass.framebuffer, nullptr);
    common::destroyImage(device, pass.gbuffer.depth);
    common::destroyImage(device, pass.gbuffer.albedo);
    vkDestroyRenderPass(device.handle, pass.renderPass, nullptr);
    pass = {};
}
