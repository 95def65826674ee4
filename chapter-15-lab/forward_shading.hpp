// chapter-15-lab: forward shading (--shading forward), to measure deferred shading against. No
// G-buffer and no light pass: the scene pass's fragment shader (forward.frag) shades each fragment
// it draws with every light, into the light pass's output, which the post pass then presents as
// usual. It borrows chapter-15's scene pass -- made with a depth-only layout (kForwardDepthOnly:
// no colour attachment is allocated), for its first three sets, draw order and depth attachment
// -- and the light pass's lights, scene info and output (made without a pipeline); so the two
// renderers differ only in where the shading happens: per fragment drawn (forward) or per pixel
// of the G-buffer (deferred). Forward+ (a depth pre-pass, then tile lists for a forward pass) is
// not built.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/app/cli.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/vk/device.hpp"

enum class Shading { Deferred, Forward };

// Reads --shading, refusing (InputError) what needs a G-buffer with forward shading: --light-pass
// compute, --light-culling tiled, a --view other than final, a --gbuffer other than book.
Shading readShading(const common::Options& options);

struct ForwardPass {
    ScenePipelines pipelines;  // forward.frag into the light output, with the scene pass's depth
};

ForwardPass createForwardPass(const common::Device& device, VkPipelineCache cache, const ScenePass& scenePass,
                              const LightPass& lightPass);
// Leaves the light output READ_ONLY_OPTIMAL for the post pass and the depth attachment
// READ_ONLY_OPTIMAL (for --dump), as the deferred passes do.
void recordForwardPass(VkCommandBuffer cmd, const ForwardPass& pass, ScenePass& scenePass,
                       const LightPass& lightPass, const common::GpuScene& scene, uint32_t frame,
                       glm::vec3 cameraPosition);
void destroyForwardPass(const common::Device& device, ForwardPass& pass);
