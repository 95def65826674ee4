// G-buffer attachments, their barriers and vkCmdBeginRendering.
#include "common/passes/gbuffer.hpp"

#include <cstdio>
#include <string>

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"

namespace common {

std::vector<VkFormat> colorFormats(const GBufferFormats& formats) {
    std::vector<VkFormat> result;
    for (VkFormat format : {formats.position, formats.albedo, formats.normal, formats.pbr})
        if (format != VK_FORMAT_UNDEFINED) result.push_back(format);
    return result;
}

uint32_t bytesPerPixel(const GBufferFormats& formats) {
    auto bytes = [](VkFormat format) -> uint32_t {
        switch (format) {
            case VK_FORMAT_UNDEFINED:
                return 0;
            case VK_FORMAT_R32G32B32A32_SFLOAT:
                return 16;
            case VK_FORMAT_R16G16B16A16_SFLOAT:
                return 8;
            case VK_FORMAT_D32_SFLOAT:
            case VK_FORMAT_X8_D24_UNORM_PACK32:
            case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            case VK_FORMAT_R16G16_UNORM:
                return 4;
            default:
                throw Failure("bytesPerPixel: a G-buffer format it does not know");
        }
    };
    return bytes(formats.position) + bytes(formats.albedo) + bytes(formats.normal) + bytes(formats.pbr) +
           bytes(formats.depth);
}

std::vector<const Image*> colorAttachments(const GBuffer& gbuffer) {
    std::vector<const Image*> result;
    for (const Image* image : {&gbuffer.position, &gbuffer.albedo, &gbuffer.normal, &gbuffer.pbr})
        if (image->handle != VK_NULL_HANDLE) result.push_back(image);
    return result;
}

void checkPositionRange(const GBufferFormats& formats, glm::vec3 boundsMin, glm::vec3 boundsMax,
                        const std::string& origin) {
    if (formats.position != VK_FORMAT_R16G16B16A16_SFLOAT) return;
    float reach = glm::max(glm::max(glm::abs(boundsMin.x), glm::abs(boundsMin.y)), glm::abs(boundsMin.z));
    reach = glm::max(reach,
                     glm::max(glm::max(glm::abs(boundsMax.x), glm::abs(boundsMax.y)), glm::abs(boundsMax.z)));
    if (!(reach <= kMaxHalfFloat)) {
        char text[64];
        std::snprintf(text, sizeof(text), "%g", double(reach));
        throw InputError(origin + ": the scene reaches " + text +
                         " on an axis; the G-buffer keeps world positions in 16-bit floats (the book's "
                         "R16G16B16A16_SFLOAT), which end at 65504: a scene is drawn within -65504..65504");
    }
}

GBuffer createGBuffer(const Device& device, VkExtent2D extent, const GBufferFormats& formats) {
    auto color = [&](VkFormat format, const char* name) {
        if (format == VK_FORMAT_UNDEFINED) return Image{};
        return createImage(device, extent, format,
                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                               VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           VK_IMAGE_ASPECT_COLOR_BIT, std::string("G-buffer ") + name);
    };
    GBuffer gbuffer;
    gbuffer.position = color(formats.position, "position");
    gbuffer.albedo = color(formats.albedo, "albedo");
    gbuffer.normal = color(formats.normal, "normal");
    gbuffer.pbr = color(formats.pbr, "pbr");
    gbuffer.depth = createImage(device, extent, formats.depth,
                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                VK_IMAGE_ASPECT_DEPTH_BIT, "G-buffer depth");
    return gbuffer;
}

void destroyGBuffer(const Device& device, GBuffer& gbuffer) {
    for (Image* image : {&gbuffer.position, &gbuffer.albedo, &gbuffer.normal, &gbuffer.pbr})
        if (image->handle != VK_NULL_HANDLE) destroyImage(device, *image);
    destroyImage(device, gbuffer.depth);
    gbuffer = {};
}

// The G-buffer's readers: the light pass's fragment shader, or its compute shader (chapter-15's
// --light-pass compute).
constexpr VkPipelineStageFlags2 kReaders =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

//> gbuffer-render-init
// Before drawing: every attachment to ATTACHMENT_OPTIMAL. The old contents are cleared, so the
// old layout is UNDEFINED; but the previous frame's light pass may still be sampling them in its
// fragment shader (or its compute shader, with --light-pass compute: kReaders), so the transition waits for
// that stage (a write-after-read hazard needs only this execution dependency).
void gbufferRenderInit(VkCommandBuffer cmd, const GBuffer& gbuffer) {
    std::vector<VkImageMemoryBarrier2> barriers;
    for (const Image* color : colorAttachments(gbuffer))
        barriers.push_back(imageBarrier(color->handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                                        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, kReaders, VK_ACCESS_2_NONE,
                                        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT));
    barriers.push_back(imageBarrier(
        gbuffer.depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, kReaders, VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT));
    pipelineBarrier(cmd, barriers.data(), uint32_t(barriers.size()));
}

// After drawing: every attachment to READ_ONLY_OPTIMAL, its writes made visible to the light
// pass's fragment shader (read after write).
void gbufferRenderFinish(VkCommandBuffer cmd, const GBuffer& gbuffer) {
    std::vector<VkImageMemoryBarrier2> barriers;
    for (const Image* color : colorAttachments(gbuffer))
        barriers.push_back(imageBarrier(
            color->handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, kReaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT));
    barriers.push_back(imageBarrier(
        gbuffer.depth.handle, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kReaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT));
    pipelineBarrier(cmd, barriers.data(), uint32_t(barriers.size()));
}
//< gbuffer-render-init

//> gbuffer-begin-rendering
void beginGBufferRendering(VkCommandBuffer cmd, const GBuffer& gbuffer, float depthClear) {
    // What a framebuffer and the render pass's attachment descriptions used to say, now given
    // at record time: one VkRenderingAttachmentInfo per colour attachment, and the depth one.
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const Image* color : colorAttachments(gbuffer))
        colors.push_back({
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = color->view,
            .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}},  // alpha 0: no surface here
        });
    VkRenderingAttachmentInfo depth{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = gbuffer.depth.view,
        .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,  // the light pass reads it (--view depth, lighting)
        .clearValue = {.depthStencil = {depthClear, 0}},
    };
    VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, gbuffer.depth.extent},
        .layerCount = 1,
        .colorAttachmentCount = uint32_t(colors.size()),
        .pColorAttachments = colors.data(),
        .pDepthAttachment = &depth,
    };
    vk13.CmdBeginRendering(cmd, &rendering);
}
//< gbuffer-begin-rendering

}  // namespace common
