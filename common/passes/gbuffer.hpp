// chapter-15's G-buffer for dynamic rendering: named attachments (position, albedo, normal, PBR
// data, depth), one set shared by all frames in flight, and the barriers that move it between
// being written (scene pass) and being sampled (light pass). chapter-14 introduces all of this,
// written out for its two attachments in chapter-14/scene_pass.cpp (the book's RenderScn
// renderInit / renderFinish); this is the same for any set of attachments, for chapter-15.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/vk/device.hpp"
#include "common/vk/image.hpp"

namespace common {

// The format of each attachment; VK_FORMAT_UNDEFINED: the layout has no such attachment (a
// layout that reconstructs position from depth stores none).
struct GBufferFormats {
    VkFormat position = VK_FORMAT_UNDEFINED;
    VkFormat albedo = VK_FORMAT_UNDEFINED;
    VkFormat normal = VK_FORMAT_UNDEFINED;
    VkFormat pbr = VK_FORMAT_UNDEFINED;  // ambient occlusion, roughness, metallic
    VkFormat depth =
        VK_FORMAT_D32_SFLOAT;  // a device without it gets X8_D24_UNORM_PACK32 (chooseDepthFormat)
};

// The colour formats that exist, in attachment order: position, albedo, normal, pbr. That order
// is the scene fragment shader's output locations and the light pass's bindings (depth last).
std::vector<VkFormat> colorFormats(const GBufferFormats& formats);
// Bytes per pixel of all attachments, depth included.
uint32_t bytesPerPixel(const GBufferFormats& formats);

// A position attachment of 16-bit floats (the book's R16G16B16A16_SFLOAT) holds world positions
// up to 65504 on each axis; beyond, a surface's position is infinite and its shading not a
// number. Throws InputError when the scene's bounds reach past that (other formats: no limit).
// Within it, the positions are spaced 2^(e-10) apart for |x| in [2^e, 2^(e+1)): 1/128 at 1,
// 8 at 10,000 (docs/accuracy.md shows what that does to the shading).
inline constexpr float kMaxHalfFloat = 65504.0f;
// `origin` names the scene in the message (its file).
void checkPositionRange(const GBufferFormats& formats, glm::vec3 boundsMin, glm::vec3 boundsMax,
                        const std::string& origin);

struct GBuffer {
    Image position;  // no handle when the layout has no position attachment
    Image albedo;    // alpha: 1 where a surface was drawn, 0 (the clear value) where none was
    Image normal;
    Image pbr;
    Image depth;
};

// The colour attachments that exist, in attachment order (see colorFormats).
std::vector<const Image*> colorAttachments(const GBuffer& gbuffer);

// Every attachment sampled by the light pass and copyable (TRANSFER_SRC: chapter-15's --dump
// reads them back).
GBuffer createGBuffer(const Device& device, VkExtent2D extent, const GBufferFormats& formats);
void destroyGBuffer(const Device& device, GBuffer& gbuffer);

// Before the scene pass: every attachment to ATTACHMENT_OPTIMAL, after the previous frame's
// light pass has sampled it.
void gbufferRenderInit(VkCommandBuffer cmd, const GBuffer& gbuffer);
// After the scene pass: every attachment to READ_ONLY_OPTIMAL, visible to the light pass.
void gbufferRenderFinish(VkCommandBuffer cmd, const GBuffer& gbuffer);
// vkCmdBeginRendering on all attachments, cleared to zero (depth to `depthClear`: 1, or 0 with
// reversed-Z) and stored.
void beginGBufferRendering(VkCommandBuffer cmd, const GBuffer& gbuffer, float depthClear);

}  // namespace common
