// Image decoding (stb_image), mip chains (a box filter; stb_image_resize for odd sizes), texture
// upload, samplers.
#include "common/vk/texture.hpp"

#include <stb_image.h>
#include <stb_image_resize.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/checked.hpp"
#include "common/core/files.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

// One mip level from the one above when both sides are even: each texel the mean of a 2x2 block,
// colour weighted by alpha where it is coverage (`weighted`: a transparent texel's colour does
// not bleed into its neighbours), in
// linear light for sRGB data. The result is what stb_image_resize's box filter gives for these
// sizes (its sRGB tables round slightly differently, by at most 1), about three times faster: on a
// book-sized model the mip chains were most of the start-up (docs/performance.md). Odd sizes go
// to stb.
void halveEven(const uint8_t* above, int width, int height, uint8_t* out, bool srgb, bool weighted) {
    struct Tables {
        float toLinear[256];
        uint8_t toSrgb[65536];  // linear in [0, 1] at 16 bits: fine enough for sRGB's darkest steps
        Tables() {
            for (int i = 0; i < 256; ++i) {
                float c = float(i) / 255.0f;
                toLinear[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
            }
            for (int i = 0; i < 65536; ++i) {
                float l = (float(i) + 0.5f) / 65536.0f;
                float c = l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
                toSrgb[i] = uint8_t(std::clamp(c * 255.0f + 0.5f, 0.0f, 255.0f));
            }
        }
    };
    static const Tables tables;
    const int outWidth = width / 2, outHeight = height / 2;
    const size_t row = size_t(width) * 4;
    for (int y = 0; y < outHeight; ++y) {
        const uint8_t* top = above + size_t(2 * y) * row;
        const uint8_t* bottom = top + row;
        uint8_t* texel = out + size_t(y) * size_t(outWidth) * 4;
        for (int x = 0; x < outWidth; ++x, top += 8, bottom += 8, texel += 4) {
            const uint8_t* block[4] = {top, top + 4, bottom, bottom + 4};
            float alpha = 0.0f, colour[3] = {0.0f, 0.0f, 0.0f}, plain[3] = {0.0f, 0.0f, 0.0f};
            for (const uint8_t* t : block) {
                float a = float(t[3]) * (1.0f / 255.0f);
                alpha += a;
                if (!weighted) a = 1.0f;  // alpha is data: every channel on its own
                for (int c = 0; c < 3; ++c) {
                    float v = srgb ? tables.toLinear[t[c]] : float(t[c]) * (1.0f / 255.0f);
                    colour[c] += v * a;
                    plain[c] += v;
                }
            }
            for (int c = 0; c < 3; ++c) {
                float v = !weighted ? colour[c] * 0.25f : alpha > 0.0f ? colour[c] / alpha : plain[c] * 0.25f;
                v = std::clamp(v, 0.0f, 1.0f);
                texel[c] =
                    srgb ? tables.toSrgb[std::min(int(v * 65536.0f), 65535)] : uint8_t(v * 255.0f + 0.5f);
            }
            texel[3] = uint8_t(alpha * (255.0f / 4.0f) + 0.5f);
        }
    }
}

// stb_image decodes more formats than a model's textures come in, and not all of its decoders
// are safe on hostile input (its Radiance HDR reader loops forever on a truncated run,
// CVE-2021-42715). Textures are PNG, JPEG, BMP or TGA: the others are refused by their magic
// bytes before any decoder runs.
void checkImageFormat(const uint8_t* head, size_t size, const std::string& name) {
    auto starts = [&](const char* magic, size_t length) {
        return size >= length && std::memcmp(head, magic, length) == 0;
    };
    const char* format = starts("#?RADIANCE", 10) || starts("#?RGBE", 6) ? "a Radiance HDR image"
                         : starts("GIF8", 4)                             ? "a GIF image"
                         : starts("8BPS", 4)                             ? "a Photoshop image"
                         : starts("\x53\x80\xf6\x34", 4)                 ? "a Softimage PIC image"
                         : size >= 2 && head[0] == 'P' && (head[1] == '5' || head[1] == '6') ? "a PNM image"
                                                                                             : nullptr;
    if (format)
        throw InputError(name + ": " + format + "; textures are read from PNG, JPEG, BMP or TGA images");
}

// What the whole of an image's bytes must hold before stb_image decodes them. A progressive
// JPEG's every scan walks the whole image again (a scan costs 14 bytes of file: 5,000 of them make
// 50 KB take half a minute at 16384x16384); real files have about 10. An uncompressed BMP or
// TGA shorter than its header's pixels is decoded by stb_image as if the rest were zeros.
constexpr size_t kMaxJpegScans = 100;
void checkImageBytes(const uint8_t* bytes, size_t size, const std::string& name) {
    auto le = [&](size_t at, int n) {
        uint64_t v = 0;
        for (int i = n - 1; i >= 0; --i) v = v << 8 | bytes[at + size_t(i)];
        return v;
    };
    if (size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) {
        // 0xFF 0xDA starts a scan; inside a scan's data every 0xFF is followed by 0x00 or a
        // restart marker, so each pair counts one scan.
        size_t scans = 0;
        for (size_t i = 0; i + 1 < size; ++i)
            if (bytes[i] == 0xff && bytes[i + 1] == 0xda && ++scans > kMaxJpegScans)
                throw InputError(name + ": a JPEG of more than " + std::to_string(kMaxJpegScans) +
                                 " scans (each one decodes the whole image again)");
    } else if (size >= 34 && bytes[0] == 'B' && bytes[1] == 'M') {
        const uint64_t offset = le(10, 4), width = le(18, 4), bits = le(28, 2), compression = le(30, 4);
        const int64_t height = int32_t(uint32_t(le(22, 4)));
        if ((compression == 0 || compression == 3) && width <= (1u << 16) && bits <= 32) {
            const uint64_t row = (width * bits + 31) / 32 * 4;
            const uint64_t need =
                saturatingAdd(offset, saturatingMul(row, uint64_t(height < 0 ? -height : height)));
            if (need > size)
                throw InputError(name + ": corrupt image (its pixels end at byte " + std::to_string(size) +
                                 " of " + std::to_string(need) + ")");
        }
    } else if (size >= 18 && (bytes[2] == 2 || bytes[2] == 3) && bytes[1] <= 1) {
        // An uncompressed TGA (type 2, true colour, or 3, grey); RLE types are not sized ahead.
        const uint64_t colorMap = bytes[1] ? le(5, 2) * ((bytes[7] + 7) / 8) : 0;
        const uint64_t need =
            saturatingAdd(18 + uint64_t(bytes[0]) + colorMap,
                          saturatingMul(le(12, 2) * le(14, 2), (uint64_t(bytes[16]) + 7) / 8));
        if (need > size)
            throw InputError(name + ": corrupt image (its pixels end at byte " + std::to_string(size) +
                             " of " + std::to_string(need) + ")");
    }
}

}  // namespace

ImageExtent readImageExtent(const std::filesystem::path& path, uint32_t maxDimension) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(utf8(path) + ": no such image file");
    {
        unsigned char head[16] = {};
        std::ifstream in(path, std::ios::binary);
        in.read(reinterpret_cast<char*>(head), sizeof(head));
        checkImageFormat(head, size_t(in.gcount()), utf8(path));
    }
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
    return {uint32_t(width), uint32_t(height)};
}

ImageExtent readImageExtent(const uint8_t* bytes, size_t size, const std::string& name,
                            uint32_t maxDimension) {
    if (size == 0 || size > size_t(INT32_MAX))
        throw InputError(name + ": not a readable image (empty or too large)");
    checkImageFormat(bytes, size, name);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels))
        throw InputError(name + ": not a readable image (" + stbi_failure_reason() + ")");
    if (width <= 0 || height <= 0 || uint32_t(width) > maxDimension || uint32_t(height) > maxDimension)
        throw InputError(name + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the device limit of " + std::to_string(maxDimension));
    return {uint32_t(width), uint32_t(height)};
}

uint64_t mipChainBytes(ImageExtent extent) {
    uint64_t total = 0;
    for (uint64_t w = std::max(extent.width, 1u), h = std::max(extent.height, 1u);;
         w = std::max<uint64_t>(w / 2, 1), h = std::max<uint64_t>(h / 2, 1)) {
        total = saturatingAdd(total, saturatingMul(saturatingMul(w, h), 4));
        if (w == 1 && h == 1) return total;
    }
}

Pixels loadPixels(const std::filesystem::path& path, uint32_t maxDimension) {
    readImageExtent(path, maxDimension);  // the header's size, checked before reading it whole
    const std::string bytes = readInputFile(path);
    return decodePixels(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), utf8(path),
                        maxDimension);
}

Pixels decodePixels(const uint8_t* bytes, size_t size, const std::string& name, uint32_t maxDimension) {
    readImageExtent(bytes, size, name, maxDimension);  // the header's size, checked before decoding
    checkImageBytes(bytes, size, name);
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (!data) throw InputError(name + ": corrupt image (" + stbi_failure_reason() + ")");
    Pixels pixels{uint32_t(width), uint32_t(height), {}};
    pixels.rgba.assign(data, data + size_t(width) * size_t(height) * 4);
    stbi_image_free(data);
    return pixels;
}

bool linearFilterable(const Device& device, VkFormat format) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
    return properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
}

MipChain makeMipChain(const Pixels& pixels, VkFormat format, bool mipmapped, MipAlpha alpha) {
    uint32_t mipLevels = 1;
    if (mipmapped)
        for (uint32_t size = std::max(pixels.width, pixels.height); size > 1; size /= 2) ++mipLevels;

    // The mip chain is made here on the CPU, each level a 2x2 box filter of the one above (in
    // linear light for an _SRGB format, colour weighted by alpha where alpha is coverage: halveEven, or
    // stb_image_resize where a side is odd), and goes up with level 0 in one copy. The book blits each level
    // into the next on the GPU instead; on lavapipe the first blits cost ~110 ms of startup (llvmpipe
    // compiles its blit shaders then), the CPU chain of a 1024x1024 texture ~7 ms
    // (docs/performance.md).
    MipChain chain{{pixels.width, pixels.height}, format, {}, {}};
    size_t total = 0;
    for (uint32_t level = 0, w = pixels.width, h = pixels.height; level < mipLevels;
         ++level, w = std::max(w / 2, 1u), h = std::max(h / 2, 1u))
        total += size_t(w) * h * 4;
    chain.bytes.reserve(total);
    chain.bytes.assign(pixels.rgba.begin(), pixels.rgba.end());
    int width = int(pixels.width), height = int(pixels.height);
    size_t above = 0;  // offset of the level above in `bytes`
    for (uint32_t level = 0; level < mipLevels; ++level) {
        if (level > 0) {
            int nextWidth = std::max(width / 2, 1), nextHeight = std::max(height / 2, 1);
            size_t offset = chain.bytes.size();
            chain.bytes.resize(offset + size_t(nextWidth) * size_t(nextHeight) * 4);
            bool srgb = format == VK_FORMAT_R8G8B8A8_SRGB, weighted = alpha == MipAlpha::Coverage;
            if (width % 2 == 0 && height % 2 == 0)
                halveEven(chain.bytes.data() + above, width, height, chain.bytes.data() + offset, srgb,
                          weighted);
            else if (!stbir_resize_uint8_generic(
                         chain.bytes.data() + above, width, height, 0, chain.bytes.data() + offset, nextWidth,
                         nextHeight, 0, 4, weighted ? 3 : STBIR_ALPHA_CHANNEL_NONE, 0, STBIR_EDGE_WRAP,
                         STBIR_FILTER_BOX, srgb ? STBIR_COLORSPACE_SRGB : STBIR_COLORSPACE_LINEAR, nullptr))
                throw std::runtime_error("stb_image_resize failed on a mip level");
            above = offset;
            width = nextWidth;
            height = nextHeight;
        }
        chain.regions.push_back({
            .bufferOffset = above,
            .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1},
            .imageExtent = {uint32_t(width), uint32_t(height), 1},
        });
    }
    return chain;
}

Image uploadMipChain(const Device& device, StagingBatch& batch, const MipChain& chain,
                     const std::string& name) {
    const uint32_t mipLevels = uint32_t(chain.regions.size());
    Image image = createImage(device, chain.extent, chain.format,
                              VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT, name, mipLevels);

    Buffer staging = createBuffer(device, chain.bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  "staging: " + name);
    std::memcpy(staging.mapped, chain.bytes.data(), chain.bytes.size());
    batch.stagingBuffers.push_back(staging);

    VkCommandBuffer cmd = batch.commandBuffer;
    VkImageMemoryBarrier toTransfer =
        layoutBarrier(image.handle, VK_IMAGE_ASPECT_COLOR_BIT, mipLevels, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toTransfer);
    vkCmdCopyBufferToImage(cmd, staging.handle, image.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, mipLevels,
                           chain.regions.data());
    VkImageMemoryBarrier toShader = layoutBarrier(
        image.handle, VK_IMAGE_ASPECT_COLOR_BIT, mipLevels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toShader);
    return image;
}

Image uploadTexture(const Device& device, StagingBatch& batch, const Pixels& pixels, VkFormat format,
                    const std::string& name) {
    // A full mip chain when the format can be sampled with linear filtering (the usual case).
    // Its alpha is coverage (the GUI's font atlas) or opaque (the default textures).
    return uploadMipChain(device, batch,
                          makeMipChain(pixels, format, linearFilterable(device, format), MipAlpha::Coverage),
                          name);
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
    nameObject(device.handle, sampler, "sampler");
    return sampler;
}

}  // namespace common
