// chapter-15-lab: the shadow study (shadow_study.hpp).
#include "shadow_study.hpp"

#include <array>
#include <cstring>
#include <optional>

#include "chapter-15/gpu_types.hpp"
#include "chapter-16/shadow_controls.hpp"
#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/texture.hpp"

ShadowStudyOptions readShadowStudy(const common::Options& options) {
    auto chosen = [&](const char* name) {
        auto found = options.choices.find(name);
        return found == options.choices.end() ? 0u : found->second;
    };
    ShadowStudyOptions study;
    uint32_t shadows = chosen("shadows");
    study.enabled = shadows != 0;
    if (!study.enabled) {
        for (const char* name : {"shadow-layers", "cascades", "shadow-map-size"})
            if (options.choices.count(name))
                throw common::InputError(std::string("--") + name + " needs --shadows");
        if (options.view == 6) throw common::InputError("--view visibility needs --shadows");
        return study;
    }
    // chapter-16's light pass: the full-screen triangle over the whole G-buffer, deferred.
    if (chosen("light-pass") != 0)
        throw common::InputError("--shadows shades with the fragment light pass, not --light-pass compute");
    if (chosen("light-culling") != 0)
        throw common::InputError("--shadows loops over every light: no --light-culling tiled");
    if (chosen("shading") != 0)
        throw common::InputError("--shadows reads the G-buffer: no --shading forward");
    if (chosen("gbuffer") == 2)  // labLayouts(): book, reference, compact
        throw common::InputError("--shadows reads the G-buffer's positions: --gbuffer book or reference");
    study.filter = ShadowFilter(shadows - 1);
    study.layers = ShadowLayers(chosen("shadow-layers"));
    study.cascades.count = kCascadeCounts[chosen("cascades")];  // chapter-16's values
    study.cascades.mapSize = kShadowMapSizes[chosen("shadow-map-size")];
    return study;
}

std::string shadowFilterName(ShadowFilter filter) {
    const char* names[] = {"vsm", "pcf2", "pcf3", "pcf5", "vsm16", "depth"};
    return names[int(filter)];
}

bool hardwarePcf(const common::Device& device, VkFormat depthFormat) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, depthFormat, &properties);
    return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
}

std::string shadowLightShader(const ShadowStudyOptions& options, bool hardware) {
    // vsm16 reads its moments as vsm does (the sampler returns floats whatever the format).
    ShadowFilter filter =
        options.filter == ShadowFilter::Variance16 ? ShadowFilter::Variance : options.filter;
    std::string name = "chapter-15-lab/light-shadows-" + shadowFilterName(filter);
    if (filter != ShadowFilter::Variance && filter != ShadowFilter::Depth && !hardware) name += "-gather";
    return name + ".frag";
}

namespace {

// The filters that draw moments (the rest draw the depth alone).
bool variance(const ShadowStudy& study) {
    return study.options.filter == ShadowFilter::Variance || study.options.filter == ShadowFilter::Variance16;
}

// The pipeline for the study's form, made by chapter-16's createShadowPipeline: chapter-16's
// vertex and geometry shaders (one pass, gl_Layer), or the lab's vertex shader that takes the
// cascade from gl_ViewIndex (multiview) or gl_InstanceIndex (a pass per cascade, drawn with the
// cascade as firstInstance); chapter-16's fragment shader for the moments, or the lab's that
// writes depth alone. (The lab compiles chapter-16's shaders into its own directory.)
VkPipeline makeStudyPipeline(const common::Device& device, VkPipelineCache cache, const ShadowStudy& study,
                             bool alphaTest) {
    ShadowLayers layers = study.options.layers;
    ShadowPipelineShaders shaders{
        .vertex = layers == ShadowLayers::GeometryShader ? "chapter-15-lab/shadow.vert"
                  : layers == ShadowLayers::Multiview    ? "chapter-15-lab/shadow_cascade-multiview.vert"
                                                         : "chapter-15-lab/shadow_cascade.vert",
        .geometry = layers == ShadowLayers::GeometryShader ? "chapter-15-lab/shadow.geom" : nullptr,
        .fragment = variance(study) ? "chapter-15-lab/shadow.frag" : "chapter-15-lab/shadow_depth.frag",
        .moments = variance(study),
        .momentsFormat = study.momentsFormat,
        .viewMask = layers == ShadowLayers::Multiview ? (1u << study.options.cascades.count) - 1u : 0u};
    return createShadowPipeline(device, cache, study.pipelineLayout, study.depthFormat, shaders, alphaTest);
}

VkImageView layerView(const common::Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect,
                      uint32_t layer) {
    VkImageViewCreateInfo viewInfo{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                   .image = image,
                                   .viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                                   .format = format,
                                   .subresourceRange = {aspect, 0, 1, layer, 1}};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device.handle, &viewInfo, nullptr, &view));
    common::nameObject(device.handle, view, "shadow study: layer " + std::to_string(layer));
    return view;
}

}  // namespace

ShadowStudy createShadowStudy(const common::Device& device, VkPipelineCache cache,
                              const ShadowStudyOptions& options, const ScenePass& scenePass,
                              uint32_t framesInFlight) {
    ShadowStudy study;
    study.options = options;
    study.depthFormat = scenePass.formats.depth;
    study.momentsFormat =
        options.filter == ShadowFilter::Variance16 ? VK_FORMAT_R16G16_SFLOAT : kMomentsFormat;
    const CascadeSettings& settings = options.cascades;
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, study.momentsFormat, &properties);
    VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    if (variance(study) && (properties.optimalTilingFeatures & needed) != needed)
        throw common::Failure(
            std::string("this device cannot render to and sample ") +
            (options.filter == ShadowFilter::Variance16 ? "R16G16_SFLOAT" : "R32G32_SFLOAT") +
            ", the variance map's format");
    vkGetPhysicalDeviceFormatProperties(device.physical, study.depthFormat, &properties);
    // Sampled in both forms: PCF reads it, and the light pass's binding 2 holds it either way.
    if ((properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) == 0)
        throw common::Failure("this device cannot sample its depth format: no depth comparison");
    study.hardwarePcf = hardwarePcf(device, study.depthFormat);

    // The variance map renders the moments; PCF reads the depth. The other binding gets a 1x1
    // stand-in (every binding must be written).
    uint32_t momentsSize = variance(study) ? settings.mapSize : 1u;
    uint32_t momentsLayers = variance(study) ? settings.count : 1u;
    study.moments =
        common::createLayeredImage(device, {momentsSize, momentsSize}, momentsLayers, study.momentsFormat,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT, "shadow study: moments");
    study.depth = common::createLayeredImage(
        device, {settings.mapSize, settings.mapSize}, settings.count, study.depthFormat,
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
        "shadow study: depth");
    if (options.layers == ShadowLayers::PassPerCascade)
        for (uint32_t layer = 0; layer < settings.count; ++layer) {
            study.depthLayers.push_back(
                layerView(device, study.depth.handle, study.depthFormat, VK_IMAGE_ASPECT_DEPTH_BIT, layer));
            if (variance(study))
                study.momentLayers.push_back(layerView(device, study.moments.handle, study.momentsFormat,
                                                       VK_IMAGE_ASPECT_COLOR_BIT, layer));
        }

    study.cascadesLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT)},
        "shadow study: cascades");
    study.readLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
         common::binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
         // chapter-16's moving casters' map (shadows.glsl): the study has none, the moments
         // stand in (never read: the uniform's `moving` is 0).
         common::binding(3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "light: shadow study");
    study.descriptorPool =
        common::createDescriptorPool(device, 2 * framesInFlight,
                                     {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2 * framesInFlight},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * framesInFlight}},
                                     "shadow study");
    study.momentsSampler =
        common::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    // PCF in the sampler: each lookup compares the reference depth with the 2x2 texels around it
    // and filters the four results bilinearly (1 where the point is no deeper than the map).
    // Without linear filtering of depth, NEAREST: the shader gathers the four comparisons.
    VkFilter filter = study.hardwarePcf ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    VkSamplerCreateInfo compareInfo{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                    .magFilter = filter,
                                    .minFilter = filter,
                                    .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                    .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .compareEnable = VK_TRUE,
                                    .compareOp = VK_COMPARE_OP_LESS_OR_EQUAL,
                                    .maxLod = 0.0f};
    VK_CHECK(vkCreateSampler(device.handle, &compareInfo, nullptr, &study.depthSampler));
    common::nameObject(device.handle, study.depthSampler, "shadow study: depth comparison");
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        study.cascades.push_back(common::createBuffer(device, sizeof(CascadeUniform),
                                                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, hostVisible,
                                                      "shadow study: cascades"));
        VkBuffer buffer = study.cascades.back().handle;
        study.cascadesSets.push_back(common::allocateDescriptorSet(
            device, study.descriptorPool, study.cascadesLayout, "shadow study: cascades"));
        common::writeBufferDescriptor(device, study.cascadesSets.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      buffer, sizeof(CascadeUniform));
        study.readSets.push_back(common::allocateDescriptorSet(device, study.descriptorPool, study.readLayout,
                                                               "light: shadow study"));
        // depth: the depth image where chapter-16 reads its moments, through the same nearest
        // sampler (no comparison: the shader compares the texel's depth itself).
        bool depthAlone = options.filter == ShadowFilter::Depth;
        common::writeImageDescriptor(device, study.readSets.back(), 0, study.momentsSampler,
                                     depthAlone ? study.depth.view : study.moments.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        common::writeBufferDescriptor(device, study.readSets.back(), 1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      buffer, sizeof(CascadeUniform));
        common::writeImageDescriptor(device, study.readSets.back(), 2, study.depthSampler, study.depth.view,
                                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        common::writeImageDescriptor(device, study.readSets.back(), 3, study.momentsSampler,
                                     study.moments.view, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    }

    study.pipelineLayout =
        createShadowPipelineLayout(device, study.cascadesLayout, scenePass);  // chapter-16's
    common::nameObject(device.handle, study.pipelineLayout, "shadow study");
    study.opaque = makeStudyPipeline(device, cache, study, false);
    study.cutout = makeStudyPipeline(device, cache, study, true);
    return study;
}

void updateShadowStudy(ShadowStudy& study, uint32_t frame, const std::vector<Cascade>& cascades,
                       const glm::mat4& cameraView) {
    CascadeUniform uniform = cascadeUniform(cascades, cameraView);  // every layer at its first texel
    std::memcpy(study.cascades[frame].mapped, &uniform, sizeof(uniform));
}

//> record-study
void recordShadowStudy(VkCommandBuffer cmd, const ShadowStudy& study, const ScenePass& scenePass,
                       const common::GpuScene& scene, uint32_t frame) {
    // Both images to ATTACHMENT_OPTIMAL once the previous frame's light pass has read them, their
    // contents dropped (cleared below).
    VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    std::vector<VkImageMemoryBarrier2> init{common::imageBarrier(
        study.depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | depthStages,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthStages,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
    if (variance(study))
        init.push_back(common::imageBarrier(
            study.moments.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT));
    else  // PCF, depth: the moments' 1x1 stand-in in the layout its descriptor names (nothing reads it)
        init.push_back(common::imageBarrier(
            study.moments.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT));
    common::pipelineBarrier(cmd, init.data(), uint32_t(init.size()));

    uint32_t size = study.options.cascades.mapSize, count = study.options.cascades.count;
    bool perCascade = study.options.layers == ShadowLayers::PassPerCascade;
    // One rendering for every layer (gl_Layer, or one view per cascade), or one per layer.
    for (uint32_t pass = 0; pass < (perCascade ? count : 1u); ++pass) {
        VkRenderingAttachmentInfo color{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = perCascade && variance(study) ? study.momentLayers[pass] : study.moments.view,
            .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{1.0f, 1.0f, 0.0f, 0.0f}}}};
        VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = perCascade ? study.depthLayers[pass] : study.depth.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .clearValue = {.depthStencil = {1.0f, 0}}};
        bool multiview = study.options.layers == ShadowLayers::Multiview;
        VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                  .renderArea = {{0, 0}, {size, size}},
                                  .layerCount = multiview || perCascade ? 1u : count,
                                  .viewMask = multiview ? (1u << count) - 1u : 0u,
                                  .colorAttachmentCount = variance(study) ? 1u : 0u,
                                  .pColorAttachments = &color,
                                  .pDepthAttachment = &depth};
        common::vk13.CmdBeginRendering(cmd, &rendering);
        VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        VkRect2D scissor{{0, 0}, {size, size}};
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        std::array<VkDescriptorSet, 2> shared{study.cascadesSets[frame], scenePass.materialsSet};
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, study.pipelineLayout, 0, 2,
                                shared.data(), 0, nullptr);
        // chapter-16's draws; a pass per cascade tells the vertex shader its cascade as the
        // instance index, chapter-16's geometry shader takes it as the layers to draw (all).
        bool geometry = study.options.layers == ShadowLayers::GeometryShader;
        recordShadowDraws(cmd, study.pipelineLayout, study.opaque, study.cutout, scenePass, scene,
                          geometry ? (1u << count) - 1u : pass);
        common::vk13.CmdEndRendering(cmd);
    }

    // Both to READ_ONLY_OPTIMAL for the light pass's fragment shader.
    std::vector<VkImageMemoryBarrier2> finish{common::imageBarrier(
        study.depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT)};
    if (variance(study))
        finish.push_back(common::imageBarrier(
            study.moments.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT));
    common::pipelineBarrier(cmd, finish.data(), uint32_t(finish.size()));
}
//< record-study

void remakeShadowStudyPipelines(const common::Device& device, VkPipelineCache cache, ShadowStudy& study,
                                const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (!reload.changed({"chapter-15-lab/shadow.vert", "chapter-15-lab/shadow.geom",
                         "chapter-15-lab/shadow.frag", "chapter-15-lab/shadow_cascade.vert",
                         "chapter-15-lab/shadow_cascade-multiview.vert", "chapter-15-lab/shadow_depth.frag"}))
        return;
    common::replacePipeline(swap, study.opaque,
                            [&] { return makeStudyPipeline(device, cache, study, false); });
    common::replacePipeline(swap, study.cutout,
                            [&] { return makeStudyPipeline(device, cache, study, true); });
}

void destroyShadowStudy(const common::Device& device, ShadowStudy& study) {
    vkDestroyPipeline(device.handle, study.cutout, nullptr);
    vkDestroyPipeline(device.handle, study.opaque, nullptr);
    vkDestroyPipelineLayout(device.handle, study.pipelineLayout, nullptr);
    vkDestroySampler(device.handle, study.depthSampler, nullptr);
    vkDestroySampler(device.handle, study.momentsSampler, nullptr);
    vkDestroyDescriptorPool(device.handle, study.descriptorPool, nullptr);
    for (common::Buffer& buffer : study.cascades) common::destroyBuffer(device, buffer);
    vkDestroyDescriptorSetLayout(device.handle, study.readLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, study.cascadesLayout, nullptr);
    for (VkImageView view : study.depthLayers) vkDestroyImageView(device.handle, view, nullptr);
    for (VkImageView view : study.momentLayers) vkDestroyImageView(device.handle, view, nullptr);
    common::destroyImage(device, study.depth);
    common::destroyImage(device, study.moments);
    study = {};
}
