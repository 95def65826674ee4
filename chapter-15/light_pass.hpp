// chapter-15: the light pass -- Cook-Torrance lighting of the G-buffer by the scene's lights into
// an R32G32B32A32_SFLOAT image; the post pass (common/passes/post_pass.cpp) presents it. The book's
// LightRender (chapter 15): a full-screen triangle.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/passes/fullscreen.hpp"
#include "common/passes/gbuffer.hpp"
#include "common/scene/scene.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "gpu_types.hpp"

inline constexpr VkFormat kLightOutputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// What the light pass owns per frame in flight: this frame's lights and scene info, host-visible
// (the keys move the lights, the camera moves), and the descriptor sets that bind them.
struct LightFrame {
    common::Buffer lights;  // scalar layout, ShaderLight[lightCapacity]
    common::Buffer scene;   // scalar layout, ShaderSceneInfo
    VkDescriptorSet lightsSet = VK_NULL_HANDLE;
    VkDescriptorSet sceneSet = VK_NULL_HANDLE;
};

//> light-kinds
// How many lights of each kind the scene has: the light pass's loops are specialised to them
// (light_loop.glsl's constants). -1: not known to the pipeline (--pipelines generic), which
// loops over the scene info's light count and asks each light its kind.
struct LightKinds {
    int32_t directional = -1;
    int32_t point = -1;
    bool operator==(const LightKinds&) const = default;
};

// The specialization constants for `kinds`: constant_id 3 DIRECTIONAL_LIGHTS, 4 POINT_LIGHTS.
struct LightConstants {
    std::array<int32_t, 2> counts;
    std::array<VkSpecializationMapEntry, 2> entries{{{3, 0, sizeof(int32_t)}, {4, 4, sizeof(int32_t)}}};
    explicit LightConstants(LightKinds kinds) : counts{kinds.directional, kinds.point} {}
    VkSpecializationInfo info() const {  // points into this object: use it while this lives
        return {uint32_t(entries.size()), entries.data(), sizeof(counts), counts.data()};
    }
};
//< light-kinds

// The scene's lights as the light pass reads them: the directional ones first, then the point
// lights, each kind in the scene's order (so constant loops over each kind cover them all).
std::vector<ShaderLight> shaderLights(const common::Scene& scene);
// The kinds of `lights` (shaderLights' order).
LightKinds lightKinds(const std::vector<ShaderLight>& lights);
// Whether `lights` are `kinds.directional` directional lights followed by `kinds.point` point
// lights: what a pipeline specialised to `kinds` shades right.
bool inKindOrder(const std::vector<ShaderLight>& lights, LightKinds kinds);
// "1 directional, 1 point", or "generic": for the benchmark report.
std::string describeLightKinds(LightKinds kinds);

// How a light pass is made. The defaults are the book's: light.frag's full-screen triangle, the
// only stage that reads the pass's sets, drawing into the output as a colour attachment.
struct LightPassSetup {
    std::string fragmentShader = "chapter-15/light.frag";      // under <build>/bin/shaders/; "": no pipeline
    VkShaderStageFlags stages = VK_SHADER_STAGE_FRAGMENT_BIT;  // what reads sets 0-2
    VkImageUsageFlags outputUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;  // how the output is written
    std::vector<VkDescriptorSetLayout> moreSets;                          // the pipeline's sets 3..
    LightKinds kinds;  // what the pipeline is specialised to; the default: generic
};

struct LightPass {
    common::Image output;
    VkImageUsageFlags outputUsage = 0;
    VkDescriptorSetLayout attachmentsLayout = VK_NULL_HANDLE;  // set 0: the G-buffer
    VkDescriptorSetLayout lightsLayout = VK_NULL_HANDLE;       // set 1: lights, per frame
    VkDescriptorSetLayout sceneLayout = VK_NULL_HANDLE;        // set 2: scene info, per frame
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet attachmentsSet = VK_NULL_HANDLE;
    std::vector<LightFrame> frames;
    uint32_t lightCapacity = 0;
    LightKinds kinds;  // the pipelines' specialisation: updateLights is given lights of these kinds
    VkSampler sampler = VK_NULL_HANDLE;
    common::FullscreenPipeline pipeline;
};

// `lightCapacity`: the scene's number of lights (the buffers are sized from it).
LightPass createLightPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GBuffer& gbuffer, uint32_t framesInFlight, uint32_t lightCapacity,
                          const LightPassSetup& setup = {});
void resizeLightPass(const common::Device& device, LightPass& pass, VkExtent2D extent,
                     const common::GBuffer& gbuffer);
// Writes this frame's lights and scene info (lights.size() <= lightCapacity). Throws Failure when
// a specialised pass is given lights not in its kinds' order (inKindOrder).
void updateLights(LightPass& pass, uint32_t frame, const std::vector<ShaderLight>& lights,
                  const ShaderSceneInfo& scene);
// `moreSets`: the sets from 3 on, when the setup's pipeline has them.
void recordLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view,
                     std::span<const VkDescriptorSet> moreSets = {});
// Reads the last frame's output back (after the device is idle) and fails the run (Failure) on a
// NaN, infinite or negative value; prints what it found.
void checkLightOutput(const common::Device& device, const LightPass& pass);
void destroyLightPass(const common::Device& device, LightPass& pass);
