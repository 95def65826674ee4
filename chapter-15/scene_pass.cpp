// chapter-15: the scene pass.
#include "scene_pass.hpp"

#include <algorithm>

#include <string>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/formats.hpp"
#include "common/vk/pipeline.hpp"
#include "common/vk/texture.hpp"
#include "gpu_types.hpp"

namespace {

void createDescriptors(const common::Device& device, ScenePass& pass, const common::GpuScene& scene,
                       uint32_t framesInFlight) {
    pass.cameraLayout = common::createCameraSetLayout(device);
    pass.materialsLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "scene: materials");
    pass.texturesLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "scene: textures");

    //> material-sets
    // Sized from the scene: a camera set per frame in flight, the materials buffer, and one set
    // of four textures per material, each with the sampler the model gives it, every binding
    // written (unused ones get the defaults).
    uint32_t materials = uint32_t(scene.materials.size());
    pass.descriptorPool =
        common::createDescriptorPool(device, framesInFlight + 1 + materials,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4 * materials}},
                                     "scene");
    for (const common::GpuMaterial& material : scene.materials) {
        VkDescriptorSet set = common::allocateDescriptorSet(device, pass.descriptorPool, pass.texturesLayout,
                                                            "scene: textures");
        common::TextureBinding textures[4] = {material.albedo, material.normal, material.metalRough,
                                              material.occlusion};
        for (uint32_t binding = 0; binding < 4; ++binding)
            common::writeImageDescriptor(device, set, binding, scene.samplers[textures[binding].sampler],
                                         scene.textures[textures[binding].image].view,
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        pass.materialTextureSets.push_back(set);
    }
    //< material-sets

    pass.cameras = common::createCameraFrames(device, pass.descriptorPool, pass.cameraLayout, framesInFlight);

    //> shader-materials
    // Each material as the shaders read it: its factors, and flags for the features it uses --
    // its class, which picks the pipeline it draws with (a material without a map never samples
    // the default texture bound in its place).
    std::vector<ShaderMaterial> shaderMaterials;
    for (const common::GpuMaterial& m : scene.materials) {
        bool normalMap = m.normal.image != common::kFlatNormalTexture;
        uint32_t features = (m.albedo.image != common::kWhiteTexture ? kMaterialBaseColorMap : 0u) |
                            (normalMap ? kMaterialNormalMap : 0u) |
                            (normalMap && m.normalScale != 1.0f ? kMaterialNormalScale : 0u) |
                            (m.metalRough.image != common::kWhiteTexture ? kMaterialMetalRoughMap : 0u) |
                            (m.occlusion.image != common::kWhiteTexture ? kMaterialOcclusionMap : 0u) |
                            (m.doubleSided ? kMaterialDoubleSided : 0u);
        shaderMaterials.push_back({m.diffuse, m.roughness, m.metallic, features, m.alphaCutoff, m.normalScale,
                                   m.occlusionStrength, glm::vec2(0.0f)});
        pass.classOfMaterial.push_back({features, m.alphaTested});
    }
    pass.materialUsed = common::usedMaterials(scene);
    //< shader-materials
    common::StagingBatch batch = common::beginStaging(device);
    pass.materials = common::uploadStaged(device, batch, shaderMaterials.data(),
                                          shaderMaterials.size() * sizeof(ShaderMaterial),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");
    common::endStaging(device, batch);
    pass.materialsSet =
        common::allocateDescriptorSet(device, pass.descriptorPool, pass.materialsLayout, "scene: materials");
    common::writeBufferDescriptor(device, pass.materialsSet, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                  pass.materials.handle, VK_WHOLE_SIZE);
}

// "scene: cut-out, double-sided, base colour, normal map": what a class's pipeline is called.
std::string className(const MaterialClass& materialClass, bool generic) {
    std::string name = materialClass.alphaTest ? "scene: cut-out" : "scene: opaque";
    if (generic) name += ", generic";
    const std::pair<uint32_t, const char*> features[] = {
        {kMaterialDoubleSided, "double-sided"},  {kMaterialBaseColorMap, "base colour"},
        {kMaterialNormalMap, "normal map"},      {kMaterialNormalScale, "normal scale"},
        {kMaterialMetalRoughMap, "metal-rough"}, {kMaterialOcclusionMap, "occlusion"}};
    for (auto [bit, feature] : features)
        if ((materialClass.features & bit) != 0u) name += std::string(", ") + feature;
    return name;
}

// One pipeline per class, from the target's shaders; none left behind when one fails.
std::vector<VkPipeline> makeScenePipelineSet(const common::Device& device, VkPipelineCache cache,
                                             const ScenePipelines& pipelines, bool generic) {
    const ScenePipelineTarget& target = pipelines.target;
    //> scene-pipeline
    // The G-buffer's four colour attachments: as many formats and blend states.
    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = uint32_t(target.colorFormats.size()),
        .pColorAttachmentFormats = target.colorFormats.data(),
        .depthAttachmentFormat = target.depthFormat,
    };
    common::SceneVertexInput vertexInput;  // every attribute: normal mapping needs the tangent frame
    common::describeSceneVertexInput(vertexInput, common::kPosition | common::kNormal | common::kTangent |
                                                      common::kBitangent | common::kUv);
    //< scene-pipeline
    // Vertex pulling (chapter-18): no vertex buffers, no attributes; the vertex shader reads the mesh.
    VkPipelineVertexInputStateCreateInfo noVertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    common::ShaderModule vertex(device, target.shaders.vertex);
    common::ShaderModule fragment(device, target.shaders.fragment);
    std::vector<VkPipeline> made;
    try {
        for (const MaterialClass& materialClass : pipelines.materialClasses.classes) {
            //> class-constants
            // The class's constants (scene_surface.glsl): constant_id 0 ALPHA_TEST, 1
            // MATERIAL_FEATURES, 2 FEATURES_AT_RUN_TIME, each 4 bytes of `constants`.
            struct {
                VkBool32 alphaTest;
                uint32_t features;
                VkBool32 atRunTime;
            } constants{materialClass.alphaTest, materialClass.features, generic};
            std::array<VkSpecializationMapEntry, 3> entries{{
                {.constantID = 0, .offset = 0, .size = sizeof(VkBool32)},
                {.constantID = 1, .offset = 4, .size = sizeof(uint32_t)},
                {.constantID = 2, .offset = 8, .size = sizeof(VkBool32)},
            }};
            VkSpecializationInfo specialization{.mapEntryCount = uint32_t(entries.size()),
                                                .pMapEntries = entries.data(),
                                                .dataSize = sizeof(constants),
                                                .pData = &constants};
            //< class-constants
            bool doubleSided = (materialClass.features & kMaterialDoubleSided) != 0u;
            made.push_back(common::createGraphicsPipeline(
                device, cache,
                {
                    .name = className(materialClass, generic),
                    .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                               common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment, &specialization)},
                    .vertexInput = target.vertexInput ? &vertexInput.state : &noVertexInput,
                    // Back faces are never seen on closed meshes (the book culls none): culling them
                    // saves their fragments, and removes depth ties where a back face meets a front face
                    // at a silhouette edge -- ties that standard and reversed-Z break differently. Models
                    // wind front faces counter-clockwise; the flipped viewport keeps that orientation on
                    // screen. Double-sided materials show both faces.
                    .cullMode = doubleSided ? VkCullModeFlags(VK_CULL_MODE_NONE)
                                            : VkCullModeFlags(VK_CULL_MODE_BACK_BIT),
                    .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
                    .depthTest = true,
                    .depthWrite = true,
                    // Reversed-Z: nearer is larger.
                    .depthCompare =
                        target.reversedZ ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL,
                    .colorAttachmentCount = uint32_t(target.colorFormats.size()),
                    .layout = pipelines.layout,
                    .pNext = &rendering,
                }));
        }
    } catch (...) {
        for (VkPipeline pipeline : made) vkDestroyPipeline(device.handle, pipeline, nullptr);
        throw;
    }
    return made;
}

}  // namespace

ScenePipelines createScenePipelines(const common::Device& device, VkPipelineCache cache,
                                    const ScenePass& pass, const ScenePipelineTarget& target) {
    ScenePipelines pipelines;
    std::vector<VkDescriptorSetLayout> layouts{pass.cameraLayout, pass.materialsLayout, pass.texturesLayout};
    layouts.insert(layouts.end(), target.moreSets.begin(), target.moreSets.end());
    std::array<VkPushConstantRange, 2> pushConstants{{
        {.stageFlags = VK_SHADER_STAGE_VERTEX_BIT, .offset = 0, .size = pass.drawing.vertexConstants},
        {.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT,
         .offset = pass.drawing.materialOffset,
         .size = sizeof(uint32_t)},
    }};
    pipelines.layout = common::createPipelineLayout(device, layouts, pushConstants, "scene");

    pipelines.target = target;
    pipelines.target.vertexInput = pass.drawing.vertexInput;
    //> material-classes
    // The classes the scene's materials have (common::MaterialClasses). Generic pipelines are
    // told only what the pipeline state itself needs: the alpha test (so opaque draws keep early
    // depth testing) and the culling.
    for (size_t i = 0; i < pass.classOfMaterial.size(); ++i) {
        MaterialClass materialClass = pass.classOfMaterial[i];
        if (pass.genericPipelines) materialClass.features &= kMaterialDoubleSided;
        pipelines.materialClasses.add(materialClass, pass.materialUsed[i]);
    }
    //< material-classes
    try {
        pipelines.pipelines = makeScenePipelineSet(device, cache, pipelines, pass.genericPipelines);
    } catch (...) {
        vkDestroyPipelineLayout(device.handle, pipelines.layout, nullptr);
        throw;
    }
    pipelines.generic = pass.genericPipelines;
    return pipelines;
}

void remakeScenePipelines(const common::Device& device, VkPipelineCache cache, ScenePipelines& pipelines,
                          const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (pipelines.layout == VK_NULL_HANDLE ||
        !reload.changed({pipelines.target.shaders.vertex, pipelines.target.shaders.fragment}))
        return;
    std::vector<VkPipeline> made = makeScenePipelineSet(device, cache, pipelines, pipelines.generic);
    for (size_t i = 0; i < made.size(); ++i) swap.pipelines.emplace_back(&pipelines.pipelines[i], made[i]);
}

void destroyScenePipelines(const common::Device& device, ScenePipelines& pipelines) {
    for (VkPipeline pipeline : pipelines.pipelines) vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pipelines.layout, nullptr);
    pipelines = {};
}

ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight, const GBufferLayout& layout,
                          const SceneShaders& shaders, bool genericPipelines, const MeshDrawing& drawing) {
    ScenePass pass;
    pass.layout = &layout;
    pass.drawing = drawing;
    pass.genericPipelines = genericPipelines;
    for (VkFormat format : common::colorFormats(layout.formats)) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
        VkFormatFeatureFlags needed =
            VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
        if ((properties.optimalTilingFeatures & needed) != needed)
            throw common::Failure("this device cannot render to and sample format " + std::to_string(format) +
                                  ", which this G-buffer layout needs");
    }
    // The layout's formats, with the depth format this device renders to: D32_SFLOAT, else a
    // 24-bit one -- unless the layout is reversed-Z, which only float depth makes worthwhile.
    pass.formats = layout.formats;
    std::string reversedZ = "the G-buffer layout '" + std::string(layout.name) + "' (reversed-Z)";
    pass.formats.depth = common::chooseDepthFormat(device, layout.reversedZ, reversedZ.c_str());
    pass.gbuffer = common::createGBuffer(device, extent, pass.formats);
    createDescriptors(device, pass, scene, framesInFlight);
    std::vector<VkFormat> colorFormats = common::colorFormats(pass.formats);
    if (colorFormats.empty()) return pass;  // depth alone: its users draw with pipelines of their own
    pass.pipelines = createScenePipelines(device, cache, pass,
                                          {.shaders = shaders,
                                           .colorFormats = colorFormats,
                                           .depthFormat = pass.formats.depth,
                                           .reversedZ = layout.reversedZ});
    return pass;
}

void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent) {
    common::destroyGBuffer(device, pass.gbuffer);
    pass.gbuffer = common::createGBuffer(device, extent, pass.formats);
}

void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view) {
    common::writeCamera(pass.cameras[frame], projection, view);
}

//> record-scene
void recordScenePass(VkCommandBuffer cmd, ScenePass& pass, const common::GpuScene& scene, uint32_t frame,
                     glm::vec3 cameraPosition, const SceneDrawsRecorder& draws) {
    common::gbufferRenderInit(cmd, pass.gbuffer);
    common::beginGBufferRendering(cmd, pass.gbuffer, pass.layout->reversedZ ? 0.0f : 1.0f);
    VkExtent2D extent = pass.gbuffer.depth.extent;
    VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    std::array<VkDescriptorSet, 2> shared{pass.cameras[frame].set, pass.materialsSet};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelines.layout, 0, 2, shared.data(),
                            0, nullptr);
    if (draws)
        draws(cmd);
    else
        recordSceneDraws(cmd, pass, pass.pipelines, scene, cameraPosition);
    common::vk13.CmdEndRendering(cmd);
    common::gbufferRenderFinish(cmd, pass.gbuffer);
}

// The order of the draws: opaque ones by the distance of their bounds' centre, then cut-outs.
// Made again only when the camera has moved (a moved light marker waits for that: the order only
// saves shading work, it never changes the image).
void orderSceneDraws(ScenePass& pass, const common::GpuScene& scene, glm::vec3 cameraPosition) {
    if (pass.order.size() == scene.draws.size() && pass.orderedFrom == cameraPosition) return;
    std::vector<float> distance(scene.draws.size());
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const common::Draw& draw = scene.draws[i];
        distance[i] = glm::length(draw.center - cameraPosition);
        if (scene.materials[draw.material].alphaTested) distance[i] += 1e30f;  // after every opaque draw
    }
    pass.order.resize(scene.draws.size());
    for (uint32_t i = 0; i < pass.order.size(); ++i) pass.order[i] = i;
    std::sort(pass.order.begin(), pass.order.end(),
              [&](uint32_t a, uint32_t b) { return distance[a] < distance[b]; });
    pass.orderedFrom = cameraPosition;
}

void recordSceneDraws(VkCommandBuffer cmd, ScenePass& pass, const ScenePipelines& pipelines,
                      const common::GpuScene& scene, glm::vec3 cameraPosition) {
    orderSceneDraws(pass, scene, cameraPosition);
    VkPipeline bound = VK_NULL_HANDLE;
    for (uint32_t index : pass.order) {
        const common::Draw& draw = scene.draws[index];
        VkPipeline pipeline =
            pipelines.pipelines[pipelines.materialClasses.ofMaterial[draw.material]];  // its class's
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.layout, 2, 1,
                                &pass.materialTextureSets[draw.material], 0, nullptr);
        pass.drawing.record(cmd, pipelines.layout, pass.drawing, scene, draw, 0);
    }
}

void recordBoundMesh(VkCommandBuffer cmd, VkPipelineLayout layout, const MeshDrawing& drawing,
                     const common::GpuScene& scene, const common::Draw& draw, uint32_t firstInstance) {
    const common::GpuMesh& mesh = scene.meshes[draw.mesh];
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &mesh.vertices.handle, &offset);
    vkCmdBindIndexBuffer(cmd, mesh.indices.handle, 0, VK_INDEX_TYPE_UINT32);
    // Normals need the inverse-transpose of the model matrix: computed when the draw was
    // placed (common::setDrawModel), not once per vertex in the shader as the book does.
    const glm::mat3& normalMatrix = draw.normalMatrix;
    DrawConstants constants{draw.model,
                            {glm::vec4(normalMatrix[0], 0.0f), glm::vec4(normalMatrix[1], 0.0f),
                             glm::vec4(normalMatrix[2], 0.0f)}};
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(constants), &constants);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, drawing.materialOffset, sizeof(uint32_t),
                       &draw.material);
    vkCmdDrawIndexed(cmd, mesh.indexCount, 1, 0, 0, firstInstance);
}
//< record-scene

void destroyScenePass(const common::Device& device, ScenePass& pass) {
    destroyScenePipelines(device, pass.pipelines);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    common::destroyBuffer(device, pass.materials);
    common::destroyCameraFrames(device, pass.cameras);
    vkDestroyDescriptorSetLayout(device.handle, pass.texturesLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.materialsLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.cameraLayout, nullptr);
    common::destroyGBuffer(device, pass.gbuffer);
    pass = {};
}
