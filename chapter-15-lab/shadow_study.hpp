// chapter-15-lab: the shadow study (--shadows) -- chapter-16's cascade shadows, and what else could
// draw and filter them, measured against a reference (docs/chapter-15-lab.md, "Shadows: speed
// against error"). It builds on chapter-16's passes: its cascades (cascades.cpp), its cascade
// uniform and layered images (shadow_pass.cpp), its shadow shaders and its light loop.
//   --shadows vsm|pcf2|pcf3|pcf5|vsm16|depth: the book's variance map (moments + Chebyshev), or the
//     depth alone compared by the sampler, with percentage-closer filtering over 2x2, 3x3 or 5x5
//     texels; the variance map with half-float moments (R16G16_SFLOAT: 4 bytes a texel, not 8); or
//     the depth alone, one texel read as chapter-16 reads its moments and compared in the shader
//     (no bound, no filter: what chapter-16's read costs without the variance);
//   --shadow-layers geometry|multiview|passes: one pass with the book's geometry shader writing
//     gl_Layer; one pass with VK_KHR_multiview (core since 1.1: each cascade a view, gl_ViewIndex
//     picks its matrix, no geometry stage); or one pass per cascade, each into its own layer.
// Every cascade is drawn every frame (chapter-16's --shadow-redraw always): the study times it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "chapter-15/scene_pass.hpp"
#include "chapter-16/cascades.hpp"
#include "chapter-16/shadow_pass.hpp"
#include "common/app/cli.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

enum class ShadowFilter { Variance, Pcf2, Pcf3, Pcf5, Variance16, Depth };
enum class ShadowLayers { GeometryShader, Multiview, PassPerCascade };

struct ShadowStudyOptions {
    bool enabled = false;  // --shadows given (not none)
    ShadowFilter filter = ShadowFilter::Variance;
    ShadowLayers layers = ShadowLayers::GeometryShader;
    CascadeSettings cascades;  // --cascades, --shadow-map-size
};

// The lab's options for the study (--shadows, --shadow-layers, --cascades, --shadow-map-size);
// InputError for what the study cannot be combined with.
ShadowStudyOptions readShadowStudy(const common::Options& options);
// "vsm", "pcf3": the filter's name.
std::string shadowFilterName(ShadowFilter filter);
// Whether the device filters `depthFormat` linearly: PCF's bilinear comparisons by the sampler
// (otherwise gathered and weighed in the shader).
bool hardwarePcf(const common::Device& device, VkFormat depthFormat);
// The light pass's shader for the study: chapter-15-lab/light-shadows-vsm.frag, ...-pcf3-gather.frag.
std::string shadowLightShader(const ShadowStudyOptions& options, bool hardware);

struct ShadowStudy {
    ShadowStudyOptions options;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkFormat momentsFormat = VK_FORMAT_UNDEFINED;  // R32G32_SFLOAT (chapter-16's), R16G16_SFLOAT (vsm16)
    common::Image moments;  // the variance map's moments; 1x1, unused, for PCF and depth
    common::Image depth;    // sampled by PCF and by depth (binding 0, through the nearest sampler)
    std::vector<VkImageView> momentLayers, depthLayers;     // --shadow-layers passes: a view per layer
    VkDescriptorSetLayout cascadesLayout = VK_NULL_HANDLE;  // set 0 of the shadow pipelines
    VkDescriptorSetLayout readLayout = VK_NULL_HANDLE;      // the light pass's set 3
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::Buffer> cascades;  // CascadeUniform (chapter-16's), per frame in flight
    std::vector<VkDescriptorSet> cascadesSets, readSets;
    VkSampler momentsSampler = VK_NULL_HANDLE;  // nearest, as chapter-16's
    VkSampler depthSampler = VK_NULL_HANDLE;    // compareEnable; linear where the device filters depth
    bool hardwarePcf = false;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline opaque = VK_NULL_HANDLE;
    VkPipeline cutout = VK_NULL_HANDLE;
};

ShadowStudy createShadowStudy(const common::Device& device, VkPipelineCache cache,
                              const ShadowStudyOptions& options, const ScenePass& scenePass,
                              uint32_t framesInFlight);
void updateShadowStudy(ShadowStudy& study, uint32_t frame, const std::vector<Cascade>& cascades,
                       const glm::mat4& cameraView);
void recordShadowStudy(VkCommandBuffer cmd, const ShadowStudy& study, const ScenePass& scenePass,
                       const common::GpuScene& scene, uint32_t frame);
void destroyShadowStudy(const common::Device& device, ShadowStudy& study);
void remakeShadowStudyPipelines(const common::Device& device, VkPipelineCache cache, ShadowStudy& study,
                                const common::ShaderReload& reload, common::PipelineSwap& swap);
