// Screenshot read-back and PNG writing (stb_image_write).
#include "common/vk/screenshot.hpp"

#include <stb_image_write.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/formats.hpp"

#include <glm/gtc/packing.hpp>

namespace common {
namespace {

// One 4-byte texel of a presented image's format to 8-bit R, G, B as the display would show them
// (the values stored are already sRGB-encoded, by the hardware or by our shaders). False for a
// format we do not read.
bool decodeTexel(VkFormat format, const uint8_t* texel, uint8_t rgb[3]) {
    uint32_t packed;
    std::memcpy(&packed, texel, 4);
    auto ten = [&](int shift) {  // a 10-bit channel to 8 bits, rounded
        return static_cast<uint8_t>((((packed >> shift) & 0x3ffu) * 255u + 511u) / 1023u);
    };
    switch (format) {
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_SRGB:
            rgb[0] = texel[2], rgb[1] = texel[1], rgb[2] = texel[0];
            return true;
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_A8B8G8R8_UNORM_PACK32:  // packed ABGR in a little-endian uint32 is R,G,B,A in memory
        case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
            rgb[0] = texel[0], rgb[1] = texel[1], rgb[2] = texel[2];
            return true;
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32:  // bits 29..20 R, 19..10 G, 9..0 B
            rgb[0] = ten(20), rgb[1] = ten(10), rgb[2] = ten(0);
            return true;
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:  // bits 29..20 B, 19..10 G, 9..0 R
            rgb[0] = ten(0), rgb[1] = ten(10), rgb[2] = ten(20);
            return true;
        default:
            return false;
    }
}

}  // namespace

std::vector<uint8_t> readImage(const Device& device, VkImage image, VkExtent2D extent, VkImageLayout layout,
                               uint32_t bytesPerTexel, VkImageAspectFlags aspect) {
    VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * bytesPerTexel;
    Buffer readback =
        createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "readback");

    VkCommandBuffer cmd = beginOneTimeCommands(device);
    // Whatever wrote the image earlier on this queue (a render pass's colour or depth output, a
    // compute shader, a copy or blit) is done and visible to the copy; the image goes back to
    // `layout` afterwards, so the caller's next step (present) finds it as it left it.
    VkPipelineStageFlags writers = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkImageMemoryBarrier toTransfer =
        layoutBarrier(image, aspect, 1, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_ACCESS_MEMORY_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    vkCmdPipelineBarrier(cmd, writers, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &toTransfer);
    VkBufferImageCopy region{
        .imageSubresource = {aspect, 0, 0, 1},
        .imageExtent = {extent.width, extent.height, 1},
    };
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle, 1, &region);
    VkImageMemoryBarrier back = layoutBarrier(image, aspect, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                                              VK_ACCESS_TRANSFER_READ_BIT, 0);
    VkBufferMemoryBarrier toHost{
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER,
        .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
        .dstAccessMask = VK_ACCESS_HOST_READ_BIT,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = readback.handle,
        .size = VK_WHOLE_SIZE,
    };
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                         &toHost, 1, &back);
    submitOneTimeCommands(device, cmd);

    const auto* bytes = static_cast<const uint8_t*>(readback.mapped);
    std::vector<uint8_t> texels(bytes, bytes + size);
    destroyBuffer(device, readback);
    return texels;
}

std::vector<float> readFloatImage(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                                  VkImageLayout layout) {
    size_t count = size_t{extent.width} * extent.height * 4;
    std::vector<float> values(count);
    if (format == VK_FORMAT_R32G32B32A32_SFLOAT) {
        std::vector<uint8_t> bytes = readImage(device, image, extent, layout, 16);
        std::memcpy(values.data(), bytes.data(), bytes.size());
    } else if (format == VK_FORMAT_R16G16B16A16_SFLOAT) {
        std::vector<uint8_t> bytes = readImage(device, image, extent, layout, 8);
        for (size_t i = 0; i < count; ++i) {
            uint16_t half;
            std::memcpy(&half, bytes.data() + i * 2, 2);
            values[i] = glm::unpackHalf1x16(half);
        }
    } else if (format == VK_FORMAT_R16G16_UNORM) {
        std::vector<uint8_t> bytes = readImage(device, image, extent, layout, 4);
        for (size_t i = 0; i < count / 4; ++i)
            for (size_t c = 0; c < 2; ++c) {
                uint16_t v;
                std::memcpy(&v, bytes.data() + i * 4 + c * 2, 2);
                values[i * 4 + c] = float(v) / 65535.0f;
            }
    } else if (format == VK_FORMAT_D32_SFLOAT) {
        std::vector<uint8_t> bytes = readImage(device, image, extent, layout, 4, VK_IMAGE_ASPECT_DEPTH_BIT);
        for (size_t i = 0; i < count / 4; ++i) std::memcpy(&values[i * 4], bytes.data() + i * 4, 4);
    } else if (format == VK_FORMAT_X8_D24_UNORM_PACK32) {
        std::vector<uint8_t> bytes = readImage(device, image, extent, layout, 4, VK_IMAGE_ASPECT_DEPTH_BIT);
        for (size_t i = 0; i < count / 4; ++i) {
            uint32_t packed;
            std::memcpy(&packed, bytes.data() + i * 4, 4);
            values[i * 4] = float(packed & 0xffffffu) / 16777215.0f;
        }
    } else {
        throw Failure("readFloatImage: unsupported format " + std::to_string(format));
    }
    return values;
}

void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba, int channels, int firstChannel) {
    std::ofstream out(path, std::ios::binary);
    out << (channels == 3 ? "PF" : "Pf") << "\n"
        << width << " " << height << "\n-1.0\n";  // -1: little-endian
    std::vector<float> row(size_t(width) * size_t(channels));
    for (uint32_t y = height; y-- > 0;) {
        for (uint32_t x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                row[size_t(x) * size_t(channels) + size_t(c)] =
                    rgba[(size_t(y) * width + x) * 4 + size_t(firstChannel + c)];
        out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    if (!out) throw Failure("cannot write '" + utf8(path) + "'");
}

void saveScreenshot(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                    VkImageLayout layout, const std::filesystem::path& path) {
    uint8_t probe[4] = {}, ignored[3];
    if (!decodeTexel(format, probe, ignored))
        throw Failure("cannot take a screenshot of an image in format " + formatName(format));

    std::vector<uint8_t> texels = readImage(device, image, extent, layout, 4);
    std::vector<uint8_t> rgb(size_t{extent.width} * extent.height * 3);
    for (size_t i = 0, n = size_t{extent.width} * extent.height; i < n; ++i)
        decodeTexel(format, &texels[i * 4], &rgb[i * 3]);

    removeStaleTemporaries(path);
    RegisteredTemporary written(path);  // removed by a run cut short (run_control.hpp)
    const std::filesystem::path& temporary = written.path;
    if (!stbi_write_png(utf8(temporary).c_str(), static_cast<int>(extent.width),
                        static_cast<int>(extent.height), 3, rgb.data(), static_cast<int>(extent.width * 3)))
        throw Failure("cannot write screenshot '" + utf8(temporary) + "'");
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        throw Failure("cannot write screenshot '" + utf8(path) + "'");
    }
}

}  // namespace common
