// chapter-16: the shadow pass.
#include "shadow_pass.hpp"

#include <array>
#include <cstring>
#include <optional>
#include <string>

#include "chapter-15/gpu_types.hpp"
#include "common/core/check.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/texture.hpp"

//> shadow-pipeline
// The scene's triangles through a geometry shader into every cascade's layer. Written out here,
// as chapter-06 writes out its pipeline, for what this chapter adds: the geometry stage and depth
// clamping (casters nearer the light than the cascade's box still cast their shadow, at depth 0).
VkPipeline createShadowPipeline(const common::Device& device, VkPipelineCache cache, VkPipelineLayout layout,
                                VkFormat depthFormat, const ShadowPipelineShaders& shaders, bool alphaTest) {
    common::ShaderModule vertex(device, shaders.vertex);
    common::ShaderModule fragment(device, shaders.fragment);
    VkBool32 alphaTestConstant = alphaTest;
    VkSpecializationMapEntry entry{0, 0, sizeof(VkBool32)};
    VkSpecializationInfo specialization{1, &entry, sizeof(VkBool32), &alphaTestConstant};
    std::vector<VkPipelineShaderStageCreateInfo> stages{
        common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex)};
    std::optional<common::ShaderModule> geometry;
    if (shaders.geometry) {
        geometry.emplace(device, shaders.geometry);
        stages.push_back(common::shaderStage(VK_SHADER_STAGE_GEOMETRY_BIT, *geometry));
    }
    stages.push_back(common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment, &specialization));
    common::SceneVertexInput vertexInput;
    common::describeSceneVertexInput(vertexInput, common::kPosition | common::kUv);
    VkPipelineVertexInputStateCreateInfo noVertexInput{
        // vertex pulling (chapter-18)
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
    VkPipelineViewportStateCreateInfo viewport{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                               .viewportCount = 1,
                                               .scissorCount = 1};
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .depthClampEnable = device.depthClamp ? VK_TRUE : VK_FALSE,
        .polygonMode = VK_POLYGON_MODE_FILL,
        .cullMode = VK_CULL_MODE_NONE,  // the book's: both faces cast
        .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
        .lineWidth = 1.0f};
    VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
    VkPipelineDepthStencilStateCreateInfo depth{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = VK_TRUE,
        .depthWriteEnable = VK_TRUE,
        .depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL};
    VkPipelineColorBlendAttachmentState blend{.colorWriteMask =
                                                  VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT};
    VkPipelineColorBlendStateCreateInfo colorBlend{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
        .attachmentCount = shaders.moments ? 1u : 0u,
        .pAttachments = &blend};
    std::array<VkDynamicState, 2> dynamic{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamicState{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
        .dynamicStateCount = uint32_t(dynamic.size()),
        .pDynamicStates = dynamic.data()};
    VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                            .viewMask = shaders.viewMask,
                                            .colorAttachmentCount = shaders.moments ? 1u : 0u,
                                            .pColorAttachmentFormats = &shaders.momentsFormat,
                                            .depthAttachmentFormat = depthFormat};
    VkGraphicsPipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
        .pNext = &rendering,
        .stageCount = uint32_t(stages.size()),
        .pStages = stages.data(),
        .pVertexInputState = shaders.vertexInput ? &vertexInput.state : &noVertexInput,
        .pInputAssemblyState = &inputAssembly,
        .pViewportState = &viewport,
        .pRasterizationState = &rasterization,
        .pMultisampleState = &multisample,
        .pDepthStencilState = &depth,
        .pColorBlendState = &colorBlend,
        .pDynamicState = &dynamicState,
        .layout = layout};
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(device.handle, cache, 1, &info, nullptr, &pipeline));
    common::nameObject(device.handle, pipeline,
                       std::string(alphaTest ? "shadow: cut-out, " : "shadow: opaque, ") + shaders.vertex);
    return pipeline;
}
//< shadow-pipeline

namespace {

VkPipeline makeShadowPipeline(const common::Device& device, VkPipelineCache cache, const ShadowPass& pass,
                              bool alphaTest) {
    return createShadowPipeline(device, cache, pass.pipelineLayout, pass.depthFormat, pass.shaders,
                                alphaTest);
}

}  // namespace

VkPipelineLayout createShadowPipelineLayout(const common::Device& device, VkDescriptorSetLayout cascades,
                                            const ScenePass& scenePass) {
    // Set 0 the cascades, 1 and 2 the scene pass's materials and textures; the scene pass's push
    // constants (the model matrix for the vertex stage, the material for the fragment stage).
    std::array<VkDescriptorSetLayout, 3> layouts{cascades, scenePass.materialsLayout,
                                                 scenePass.texturesLayout};
    std::array<VkPushConstantRange, 2> pushConstants{{
        {VK_SHADER_STAGE_VERTEX_BIT, 0, scenePass.drawing.vertexConstants},
        {VK_SHADER_STAGE_FRAGMENT_BIT, scenePass.drawing.materialOffset, sizeof(uint32_t)},
    }};
    return common::createPipelineLayout(device, layouts, pushConstants, "shadow");
}

CascadeUniform cascadeUniform(const std::vector<Cascade>& cascades, const glm::mat4& cameraView) {
    CascadeUniform uniform{};
    for (size_t i = 0; i < cascades.size() && i < kMaxCascades; ++i) {
        uniform.viewProjection[i] = cascades[i].viewProjection;
        uniform.splitFar[int(i)] = cascades[i].splitFar;
        uniform.texelSize[int(i)] = cascades[i].texel;
        // The book's variance floor, 0.00002, is in depths over a range as deep as the box is
        // wide (2 (radius + texel)); the depth window is deeper (computeCascades: a step to
        // spare, or reaching the casters), and a depth difference smaller by that ratio: the
        // floor smaller by its square keeps the bound the book's for the same occluders.
        float scale =
            2.0f * (cascades[i].radius + cascades[i].texel) / (cascades[i].depthFar - cascades[i].depthNear);
        uniform.varianceFloor[int(i)] = 0.00002f * scale * scale;
    }
    uniform.cameraView = cameraView;
    uniform.count = int32_t(cascades.size());
    // The light's view looks along the light: its third row is minus that direction.
    if (!cascades.empty()) {
        const glm::mat4& view = cascades[0].view;
        uniform.toSun = glm::vec4(view[0][2], view[1][2], view[2][2], 0.0f);
    }
    return uniform;
}

ShadowPass createShadowPass(const common::Device& device, VkPipelineCache cache,
                            const CascadeSettings& settings, ShadowRedraw redraw, const ScenePass& scenePass,
                            const common::GpuScene& scene, uint32_t framesInFlight,
                            const ShadowPipelineShaders& shaders) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, kMomentsFormat, &properties);
    VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    if ((properties.optimalTilingFeatures & needed) != needed)
        throw common::Failure(
            "this device cannot render to and sample R32G32_SFLOAT, the shadow map's format");
    ShadowPass pass;
    pass.settings = settings;
    pass.shaders = shaders;
    pass.shaders.vertexInput = scenePass.drawing.vertexInput;
    pass.cache = createShadowCache(redraw, settings.mapSize, settings.count, scene.draws.size());
    // The scene pass's depth format (D32_SFLOAT, as the book's; X8_D24 on a device without it): the
    // depth only orders the casters, the moments keep their depth in 32-bit floats.
    pass.depthFormat = scenePass.formats.depth;
    // A layer per cascade and a 2D_ARRAY view over them (common/vk/image.cpp, createLayeredImage):
    // the pass renders into every layer at once, the light pass samples them as a sampler2DArray.
    VkExtent2D mapExtent{settings.mapSize, settings.mapSize};
    pass.moments =
        common::createLayeredImage(device, mapExtent, settings.count, kMomentsFormat,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT, "shadow moments");
    pass.depth = common::createLayeredImage(device, mapExtent, settings.count, pass.depthFormat,
                                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                            VK_IMAGE_ASPECT_DEPTH_BIT, "shadow depth");

    pass.cascadesLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_GEOMETRY_BIT)},
        "shadow: cascades");
    pass.readLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "light: shadows");
    pass.descriptorPool =
        common::createDescriptorPool(device, 2 * framesInFlight,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2 * framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * framesInFlight}},
                                     "shadow");
    // The moments are read as they are, one texel per sample (the book blurs nothing either).
    pass.sampler =
        common::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        pass.cascades.push_back(common::createBuffer(
            device, sizeof(CascadeUniform), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, hostVisible, "cascades"));
        pass.cascadesSets.push_back(common::allocateDescriptorSet(device, pass.descriptorPool,
                                                                  pass.cascadesLayout, "shadow: cascades"));
        common::writeBufferDescriptor(device, pass.cascadesSets.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      pass.cascades.back().handle, sizeof(CascadeUniform));
        pass.readSets.push_back(
            common::allocateDescriptorSet(device, pass.descriptorPool, pass.readLayout, "light: shadows"));
        common::writeImageDescriptor(device, pass.readSets.back(), 0, pass.sampler, pass.moments.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        common::writeBufferDescriptor(device, pass.readSets.back(), 1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      pass.cascades.back().handle, sizeof(CascadeUniform));
        // The moving casters' map, until there is one: the moments (the light pass reads binding 3
        // only for a cascade whose bit is set in `moving`).
        common::writeImageDescriptor(device, pass.readSets.back(), 3, pass.sampler, pass.moments.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    }

    pass.pipelineLayout = createShadowPipelineLayout(device, pass.cascadesLayout, scenePass);
    pass.opaque = makeShadowPipeline(device, cache, pass, false);
    pass.cutout = makeShadowPipeline(device, cache, pass, true);
    return pass;
}

namespace {

// The moving casters' map, the first time a caster moves: a second image as the moments (the
// fault layer's out-of-memory test fails this allocation), named in the light pass's sets once no
// frame in flight reads them.
void makeMovingMap(const common::Device& device, ShadowPass& pass) {
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    VkExtent2D mapExtent{pass.settings.mapSize, pass.settings.mapSize};
    pass.movingMoments =
        common::createLayeredImage(device, mapExtent, pass.settings.count, kMomentsFormat,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT, "shadow moments: moving casters");
    for (VkDescriptorSet set : pass.readSets)
        common::writeImageDescriptor(device, set, 3, pass.sampler, pass.movingMoments.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    pass.movingDefined = false;
}

}  // namespace

//> redraw
bool updateCascades(const common::Device& device, ShadowPass& pass, uint32_t frame,
                    const std::vector<Cascade>& cascades, const glm::mat4& cameraView,
                    const common::GpuScene& scene, const std::function<void()>& beforeMakingMap) {
    // Where every draw is now, for the plan's culling and for noticing which moved.
    std::vector<CasterInput> casters;
    casters.reserve(scene.draws.size());
    for (const common::Draw& draw : scene.draws) {
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        casters.push_back({draw.model, mesh.boundsMin, mesh.boundsMax, mesh.indexCount / 3, mesh.deforms});
    }
    pass.plan = planShadows(pass.cache, cascades, casters);
    bool made = !pass.plan.moving.empty() && pass.movingMoments.handle == VK_NULL_HANDLE;
    if (made && beforeMakingMap) beforeMakingMap();
    if (made) makeMovingMap(device, pass);
    CascadeUniform uniform = cascadeUniform(cascades, cameraView);
    uniform.moving = pass.plan.movingLayers;
    for (uint32_t i = 0; i < kMaxCascades; ++i)
        uniform.layerOffset[i] = glm::ivec4(pass.plan.layerOffset[i], 0, 0);
    std::memcpy(pass.cascades[frame].mapped, &uniform, sizeof(uniform));
    return made;
}
//< redraw

void invalidateShadowCache(ShadowPass& pass, ShadowRedraw redraw) {
    pass.cache.form = redraw;
    pass.cache.valid = false;
}

namespace {

// One rendering into `moments` (every layer; the depth image beside it): first `clears` (colour to
// "nothing", depth to 1), then each batch's scissor cleared in its layers and its draws drawn.
void recordShadowRendering(VkCommandBuffer cmd, const ShadowPass& pass, const ScenePass& scenePass,
                           const common::GpuScene& scene, uint32_t frame, const common::Image& moments,
                           VkImageLayout before, const std::vector<std::pair<uint32_t, TexelRect>>& clears,
                           const std::vector<ShadowBatch>& batches, bool clearBatches,
                           const ShadowDrawsRecorder& draws) {
    VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    // The moments to ATTACHMENT_OPTIMAL once earlier frames' light passes have read them, keeping
    // what the layers hold (UNDEFINED the first time: every layer is then cleared).
    std::array<VkImageMemoryBarrier2, 2> init{
        common::imageBarrier(moments.handle, VK_IMAGE_ASPECT_COLOR_BIT, before,
                             VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT),
        // The previous drawing's depth writes made available before this one's clear writes again.
        common::imageBarrier(
            pass.depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            depthStages,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
    common::pipelineBarrier(cmd, init.data(), uint32_t(init.size()));

    // Every layer at once: layerCount is the cascade count; the geometry shader sends each draw to
    // the layers its firstInstance names. What is not cleared and drawn is loaded and kept.
    uint32_t size = pass.settings.mapSize;
    VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = moments.view,
                                    .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                                    .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = pass.depth.view,
                                    .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                                    .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE};
    VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, {size, size}},
                              .layerCount = pass.settings.count,
                              .colorAttachmentCount = 1,
                              .pColorAttachments = &color,
                              .pDepthAttachment = &depth};
    common::vk13.CmdBeginRendering(cmd, &rendering);
    std::array<VkClearAttachment, 2> clearValues{
        VkClearAttachment{
            VK_IMAGE_ASPECT_COLOR_BIT, 0, {.color = {{1.0f, 1.0f, 0.0f, 0.0f}}}},  // nothing: far
        VkClearAttachment{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {.depthStencil = {1.0f, 0}}}};
    auto clear = [&](const TexelRect& r, uint32_t layer) {
        VkClearRect rect{{{r.x0, r.y0}, {uint32_t(r.x1 - r.x0), uint32_t(r.y1 - r.y0)}}, layer, 1};
        vkCmdClearAttachments(cmd, uint32_t(clearValues.size()), clearValues.data(), 1, &rect);
    };
    for (const auto& [layer, rect] : clears) clear(rect, layer);
    std::array<VkDescriptorSet, 2> shared{pass.cascadesSets[frame], scenePass.materialsSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 2, shared.data(), 0,
                            nullptr);
    VkPipeline bound = VK_NULL_HANDLE;
    for (const ShadowBatch& batch : batches) {
        if (clearBatches)
            for (uint32_t layer = 0; layer < pass.settings.count; ++layer)
                if (batch.layers >> layer & 1u) clear(batch.scissor, layer);
        if (batch.draws.empty()) continue;
        // The box's texel (0, 0) where the layer holds it; drawing only inside the scissor.
        VkViewport viewport{
            float(batch.viewport.x), float(batch.viewport.y), float(size), float(size), 0.0f, 1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        const TexelRect& r = batch.scissor;
        VkRect2D scissor{{r.x0, r.y0}, {uint32_t(r.x1 - r.x0), uint32_t(r.y1 - r.y0)}};
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        if (draws) {
            draws(cmd, batch.draws, bound);
            continue;
        }
        for (const ShadowDraw& draw : batch.draws)
            recordShadowDraw(cmd, pass.pipelineLayout, pass.opaque, pass.cutout, bound, scenePass, scene,
                             draw.draw, draw.layers);
    }
    common::vk13.CmdEndRendering(cmd);

    // The moments to READ_ONLY_OPTIMAL for the light pass's fragment shader.
    VkImageMemoryBarrier2 finish = common::imageBarrier(
        moments.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    common::pipelineBarrier(cmd, &finish, 1);
}

}  // namespace

//> record-shadow
void recordShadowPass(VkCommandBuffer cmd, ShadowPass& pass, const ScenePass& scenePass,
                      const common::GpuScene& scene, uint32_t frame, const ShadowDrawsRecorder& draws) {
    recordShadowPass(cmd, pass, pass.plan, scenePass, scene, frame, draws);
}

void recordShadowPass(VkCommandBuffer cmd, ShadowPass& pass, const ShadowPlan& plan,
                      const ScenePass& scenePass, const common::GpuScene& scene, uint32_t frame,
                      const ShadowDrawsRecorder& draws) {
    // The cached map: the layers and bands this frame draws (nothing when nothing changed).
    if (!plan.cached.empty()) {
        recordShadowRendering(
            cmd, pass, scenePass, scene, frame, pass.moments,
            pass.momentsDefined ? VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED, {},
            plan.cached, true, draws);
        pass.momentsDefined = true;
    }
    // The moving casters' map: cleared where it held casters, then this frame's moving casters.
    if (pass.movingMoments.handle == VK_NULL_HANDLE ||
        (plan.moving.empty() && plan.movingClears.empty() && pass.movingDefined))
        return;
    std::vector<std::pair<uint32_t, TexelRect>> clears = plan.movingClears;
    if (!pass.movingDefined) {  // its first frame: every layer cleared whole
        int32_t size = int32_t(pass.settings.mapSize);
        clears.clear();
        for (uint32_t layer = 0; layer < pass.settings.count; ++layer)
            clears.push_back({layer, {0, 0, size, size}});
    }
    recordShadowRendering(cmd, pass, scenePass, scene, frame, pass.movingMoments,
                          pass.movingDefined ? VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
                          clears, plan.moving, false, draws);
    pass.movingDefined = true;
}
//< record-shadow

//> shadow-draws
void recordShadowDraw(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipeline opaque, VkPipeline cutout,
                      VkPipeline& bound, const ScenePass& scenePass, const common::GpuScene& scene,
                      uint32_t drawIndex, uint32_t firstInstance) {
    const common::Draw& draw = scene.draws[drawIndex];
    VkPipeline pipeline = scene.materials[draw.material].alphaTested ? cutout : opaque;
    if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1,
                            &scenePass.materialTextureSets[draw.material], 0, nullptr);
    // The mesh, the model matrix and the material as the scene pass draws them (its MeshDrawing).
    scenePass.drawing.record(cmd, layout, scenePass.drawing, scene, draw, firstInstance);
}

void recordShadowDraws(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipeline opaque, VkPipeline cutout,
                       const ScenePass& scenePass, const common::GpuScene& scene, uint32_t firstInstance) {
    VkPipeline bound = VK_NULL_HANDLE;
    for (uint32_t i = 0; i < uint32_t(scene.draws.size()); ++i)
        recordShadowDraw(cmd, layout, opaque, cutout, bound, scenePass, scene, i, firstInstance);
}
//< shadow-draws

void remakeShadowPipelines(const common::Device& device, VkPipelineCache cache, ShadowPass& pass,
                           const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (!reload.changed({pass.shaders.vertex, pass.shaders.geometry, pass.shaders.fragment})) return;
    common::replacePipeline(swap, pass.opaque,
                            [&] { return makeShadowPipeline(device, cache, pass, false); });
    common::replacePipeline(swap, pass.cutout, [&] { return makeShadowPipeline(device, cache, pass, true); });
    pass.cache.valid = false;  // drawn again with the new shaders
}

void destroyShadowPass(const common::Device& device, ShadowPass& pass) {
    vkDestroyPipeline(device.handle, pass.cutout, nullptr);
    vkDestroyPipeline(device.handle, pass.opaque, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    for (common::Buffer& buffer : pass.cascades) common::destroyBuffer(device, buffer);
    vkDestroyDescriptorSetLayout(device.handle, pass.readLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.cascadesLayout, nullptr);
    if (pass.movingMoments.handle != VK_NULL_HANDLE) common::destroyImage(device, pass.movingMoments);
    common::destroyImage(device, pass.depth);
    common::destroyImage(device, pass.moments);
    pass = {};
}
