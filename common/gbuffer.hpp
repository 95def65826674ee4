// A G-buffer for dynamic rendering: colour attachments in attachment order plus depth, one set
// shared by all frames in flight, and the barriers that move it between being written (scene
// pass) and being sampled (light pass). Introduced by chapter-14 (the book's RenderScn
// renderInit / renderFinish); chapter-15 uses it with four colour attachments.
#pragma once

#include <vulkan/vulkan.h>

#include <span>
#include <vector>

#include "common/device.hpp"
#include "common/image.hpp"

namespace common {

struct GBuffer {
    std::vector<Image> colors;
    Image depth;
};

GBuffer createGBuffer(const Device& device, VkExtent2D extent, std::span<const VkFormat> colorFormats,
                      VkFormat depthFormat);
void destroyGBuffer(const Device& device, GBuffer& gbuffer);

// Before the scene pass: every attachment to ATTACHMENT_OPTIMAL, after the previous frame's
// light pass has sampled it.
void gbufferRenderInit(VkCommandBuffer cmd, const GBuffer& gbuffer);
// After the scene pass: every attachment to READ_ONLY_OPTIMAL, visible to the light pass.
void gbufferRenderFinish(VkCommandBuffer cmd, const GBuffer& gbuffer);
// vkCmdBeginRendering on all attachments, cleared to zero (depth to `depthClear`: 1, or 0 with
// reversed-Z) and stored.
void beginGBufferRendering(VkCommandBuffer cmd, const GBuffer& gbuffer, float depthClear = 1.0f);

}  // namespace common
