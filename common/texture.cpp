// Image decoding (stb_image), texture upload with mip generation, samplers.
#include "common/texture.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "common/check.hpp"

namespace common {
namespace {

VkImageMemoryBarrier mipBarrier(VkImage image, uint32_t level, VkImageLayout from, VkImageLayout to,
                                VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
    return {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
        .srcAccessMask = srcAccess,
        .dstAccessMask = dstAccess,
        .oldLayout = from,
        .newLayout = to,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1},
    };
}

}  // namespace

Pixels loadPixels(const std::filesystem::path& path, uint32_t maxDimension) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": no such image file");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels))
        throw InputError(path.string() + ": not a readable image (" + stbi_failure_reason() + ")");
    // Checked before decoding: a header that claims 100000 x 100000 must not allocate 40 GB.
    if (width <= 0 || height <= 0 || uint32_t(width) > maxDimension || uint32_t(height) > maxDimension)
        throw InputError(path.string() + ": image size " + std::to_string(width) + "x" +
                         std::to_string(height) + " exceeds the device limit of " +
                         std::to_string(maxDimension));
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) throw InputError(path.string() + ": corrupt image (" + stbi_failure_reason() + ")");
    Pixels pixels{uint32_t(width), uint32_t(height), {}};
    pixels.rgba.assign(data, data + size_t(width) * size_t(height) * 4);
    stbi_image_free(data);
    return pixels;
}

Image uploadTexture(const Device& device, StagingBatch& batch, const Pixels& pixels, VkFormat format) {
    // A full mip chain when the format can be blitted with linear filtering (the usual case);
    // otherwise one level.
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
    VkFormatFeatureFlags blit = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    bool canBlit = (properties.optimalTilingFeatures & blit) == blit;
    uint32_t mipLevels = 1;
    if (canBlit)
        for (uint32_t size = std::max(pixels.width, pixels.height); size > 1; size /= 2) ++mipLevels;

    Image image = createImage(
        device, {pixels.width, pixels.height}, format,
        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
        VK_IMAGE_ASPECT_COLOR_BIT, mipLevels);

    Buffer staging = createBuffer(device, pixels.rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    std::memcpy(staging.mapped, pixels.rgba.data(), pixels.rgba.size());
    batch.stagingBuffers.push_back(staging);

    VkCommandBuffer cmd = batch.commandBuffer;
    VkImageMemoryBarrier toTransfer{
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
        .srcAccessMask = 0,
        .dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
        .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
        .newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image.handle,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mipLevels, 0, 1},
    };
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toTransfer);
    VkBufferImageCopy region{
        .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
        .imageExtent = {pixels.width, pixels.height, 1},
    };
    vkCmdCopyBufferToImage(cmd, staging.handle, image.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);

    // Each level is a linear downscale of the one above: level i-1 becomes a blit source, then
    // is done and goes to SHADER_READ_ONLY.
    int32_t width = int32_t(pixels.width), height = int32_t(pixels.height);
    for (uint32_t level = 1; level < mipLevels; ++level) {
        VkImageMemoryBarrier toSource = mipBarrier(
            image.handle, level - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &toSource);
        int32_t nextWidth = std::max(width / 2, 1), nextHeight = std::max(height / 2, 1);
        VkImageBlit blitRegion{
            .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1},
            .srcOffsets = {{0, 0, 0}, {width, height, 1}},
            .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1},
            .dstOffsets = {{0, 0, 0}, {nextWidth, nextHeight, 1}},
        };
        vkCmdBlitImage(cmd, image.handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blitRegion, VK_FILTER_LINEAR);
        VkImageMemoryBarrier done = mipBarrier(image.handle, level - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                               VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_SHADER_READ_BIT);
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &done);
        width = nextWidth;
        height = nextHeight;
    }
    VkImageMemoryBarrier last = mipBarrier(image.handle, mipLevels - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                           VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &last);
    return image;
}

VkSampler createSampler(const Device& device, VkSamplerAddressMode addressMode, float maxLod) {
    VkSamplerCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = VK_FILTER_LINEAR,
        .minFilter = VK_FILTER_LINEAR,
        .mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR,
        .addressModeU = addressMode,
        .addressModeV = addressMode,
        .addressModeW = addressMode,
        .maxLod = maxLod,
        .borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK,
    };
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(device.handle, &info, nullptr, &sampler));
    return sampler;
}

}  // namespace common
