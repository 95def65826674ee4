// Image decoding (stb_image), mip chains (stb_image_resize), texture upload, samplers.
#include "common/texture.hpp"

#include <stb_image.h>
#include <stb_image_resize.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/check.hpp"
#include "common/files.hpp"

namespace common {
namespace {

VkImageMemoryBarrier textureBarrier(VkImage image, uint32_t mipLevels, VkImageLayout from, VkImageLayout to,
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
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mipLevels, 0, 1},
    };
}

}  // namespace

Pixels loadPixels(const std::filesystem::path& path, uint32_t maxDimension) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(utf8(path) + ": no such image file");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(utf8(path).c_str(), &width, &height, &channels)) {
        // stb_image refuses a PNG header of more than 2^30 bytes of pixels, then tries the other
        // formats and reports "unknown image type": read the size from the PNG header ourselves.
        unsigned char header[24] = {};
        std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(header), sizeof(header));
        if (std::memcmp(header, "\x89PNG\r\n\x1a\n", 8) == 0 && std::memcmp(header + 12, "IHDR", 4) == 0) {
            auto be32 = [](const unsigned char* b) {
                return uint32_t(b[0]) << 24 | b[1] << 16 | b[2] << 8 | b[3];
            };
            if (be32(header + 16) > maxDimension || be32(header + 20) > maxDimension)
                throw InputError(utf8(path) + ": image size " + std::to_string(be32(header + 16)) + "x" +
                                 std::to_string(be32(header + 20)) + " exceeds the device limit of " +
                                 std::to_string(maxDimension));
        }
        throw InputError(utf8(path) + ": not a readable image (" + stbi_failure_reason() + ")");
    }
    // Checked before decoding: a header that claims 100000 x 100000 must not allocate 40 GB.
    if (width <= 0 || height <= 0 || uint32_t(width) > maxDimension || uint32_t(height) > maxDimension)
        throw InputError(utf8(path) + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the device limit of " + std::to_string(maxDimension));
    stbi_uc* data = stbi_load(utf8(path).c_str(), &width, &height, &channels, 4);
    if (!data) throw InputError(utf8(path) + ": corrupt image (" + stbi_failure_reason() + ")");
    Pixels pixels{uint32_t(width), uint32_t(height), {}};
    pixels.rgba.assign(data, data + size_t(width) * size_t(height) * 4);
    stbi_image_free(data);
    return pixels;
}

Image uploadTexture(const Device& device, StagingBatch& batch, const Pixels& pixels, VkFormat format) {
    // A full mip chain when the format can be sampled with linear filtering (the usual case);
    // otherwise one level.
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
    bool filterable = properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    uint32_t mipLevels = 1;
    if (filterable)
        for (uint32_t size = std::max(pixels.width, pixels.height); size > 1; size /= 2) ++mipLevels;

    // The mip chain is made here on the CPU, each level a 2x2 box filter of the one above
    // (stb_image_resize; in linear light for an _SRGB format, colour weighted by alpha), and goes
    // up with level 0 in one copy. The book blits each level into the next on the GPU instead;
    // on lavapipe the first blits cost ~110 ms of startup (llvmpipe compiles its blit shaders
    // then), the CPU chain of a 512x512 texture ~3 ms (docs/performance.md).
    std::vector<VkBufferImageCopy> regions;
    std::vector<uint8_t> levels = pixels.rgba;
    int width = int(pixels.width), height = int(pixels.height);
    size_t above = 0;  // offset of the level above in `levels`
    for (uint32_t level = 0; level < mipLevels; ++level) {
        if (level > 0) {
            int nextWidth = std::max(width / 2, 1), nextHeight = std::max(height / 2, 1);
            size_t offset = levels.size();
            levels.resize(offset + size_t(nextWidth) * size_t(nextHeight) * 4);
            bool srgb = format == VK_FORMAT_R8G8B8A8_SRGB;
            if (!stbir_resize_uint8_generic(levels.data() + above, width, height, 0, levels.data() + offset,
                                            nextWidth, nextHeight, 0, 4, 3, 0, STBIR_EDGE_WRAP,
                                            STBIR_FILTER_BOX,
                                            srgb ? STBIR_COLORSPACE_SRGB : STBIR_COLORSPACE_LINEAR, nullptr))
                throw std::runtime_error("stb_image_resize failed on a mip level");
            above = offset;
            width = nextWidth;
            height = nextHeight;
        }
        regions.push_back({
            .bufferOffset = above,
            .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1},
            .imageExtent = {uint32_t(width), uint32_t(height), 1},
        });
    }

    Image image = createImage(device, {pixels.width, pixels.height}, format,
                              VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT, mipLevels);

    Buffer staging = createBuffer(device, levels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    std::memcpy(staging.mapped, levels.data(), levels.size());
    batch.stagingBuffers.push_back(staging);

    VkCommandBuffer cmd = batch.commandBuffer;
    VkImageMemoryBarrier toTransfer =
        textureBarrier(image.handle, mipLevels, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toTransfer);
    vkCmdCopyBufferToImage(cmd, staging.handle, image.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    VkImageMemoryBarrier toShader = textureBarrier(
        image.handle, mipLevels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toShader);
    return image;
}

VkSampler createSampler(const Device& device, VkFilter filter, VkSamplerAddressMode addressMode,
                        float maxLod) {
    VkSamplerCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = filter,
        .minFilter = filter,
        .mipmapMode =
            filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST,
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
