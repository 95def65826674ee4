// Textures: images decoded with stb_image, uploaded through a staging buffer with a full mip
// chain made on the CPU, and samplers. The book's Texture and TextureSampler (chapters 7-8).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"

namespace common {

// 8-bit RGBA pixels on the CPU, first row at the top.
struct Pixels {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// An image's size read from its header alone, nothing decoded; refused (InputError naming the
// file) when unreadable or larger than `maxDimension`, as loadPixels refuses it.
struct ImageExtent {
    uint32_t width = 0, height = 0;
};
ImageExtent readImageExtent(const std::filesystem::path& path, uint32_t maxDimension);
ImageExtent readImageExtent(const uint8_t* bytes, size_t size, const std::string& name,
                            uint32_t maxDimension);

// The bytes of an RGBA8 texture of that size with every mip level.
uint64_t mipChainBytes(ImageExtent extent);

// Decodes a PNG/JPEG/TGA/BMP file into RGBA8 (grey, 16-bit and paletted files are converted).
// Throws InputError naming the file when it is missing, corrupt or larger than `maxDimension`.
Pixels loadPixels(const std::filesystem::path& path, uint32_t maxDimension);

// The same from encoded bytes in memory (an image inside a glTF model); `name` says which in
// messages.
Pixels decodePixels(const uint8_t* bytes, size_t size, const std::string& name, uint32_t maxDimension);

// A texture's levels made on the CPU, ready for one copy: level 0 and, when `mipmapped`, every
// smaller level (2x2 box filter; in linear light for an _SRGB format). Touches no Vulkan object,
// so any thread may make one.
struct MipChain {
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::vector<uint8_t> bytes;              // every level, one after the other
    std::vector<VkBufferImageCopy> regions;  // one per level, into `bytes`
};
// What a texture's alpha means to its mip chain. Coverage (a base colour's, glTF's alpha): the
// colour is weighted by it, so a transparent texel's colour does not bleed into its neighbours.
// Independent (glTF's normal, metal-rough and occlusion maps, where alpha means nothing): every
// channel is averaged on its own.
enum class MipAlpha { Coverage, Independent };
MipChain makeMipChain(const Pixels& pixels, VkFormat format, bool mipmapped, MipAlpha alpha);
// Whether the device filters `format` linearly (then a texture of it gets a full mip chain).
bool linearFilterable(const Device& device, VkFormat format);
// Records the upload of `chain` into a new sampled image, ending in SHADER_READ_ONLY_OPTIMAL.
// Usable after endStaging(batch).
Image uploadMipChain(const Device& device, StagingBatch& batch, const MipChain& chain,
                     const std::string& name);

// makeMipChain then uploadMipChain: `pixels` into a new sampled image of `format` (an 8-bit RGBA
// format: _SRGB for colour, _UNORM for data such as normal maps).
Image uploadTexture(const Device& device, StagingBatch& batch, const Pixels& pixels, VkFormat format,
                    const std::string& name);

// A sampler. Textures: LINEAR filtering between texels and mip levels, REPEAT, maxLod
// VK_LOD_CLAMP_NONE. G-buffer attachments, read one texel per pixel: NEAREST (which every depth
// format supports; linear filtering of D32_SFLOAT is optional), CLAMP_TO_EDGE, maxLod 0.
VkSampler createSampler(const Device& device, VkFilter filter, VkSamplerAddressMode addressMode,
                        float maxLod);
}  // namespace common
