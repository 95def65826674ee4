// Textures: images decoded with stb_image, uploaded through a staging buffer with a full mip
// chain generated on the GPU, and samplers. The book's Texture and TextureSampler (chapters 7-8).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/image.hpp"

namespace common {

// 8-bit RGBA pixels on the CPU, first row at the top.
struct Pixels {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// Decodes a PNG/JPEG/TGA/BMP file into RGBA8 (grey, 16-bit and paletted files are converted).
// Throws InputError naming the file when it is missing, corrupt or larger than `maxDimension`.
Pixels loadPixels(const std::filesystem::path& path, uint32_t maxDimension);

// Records the upload of `pixels` into a new sampled image of `format` (an 8-bit RGBA format:
// _SRGB for colour, _UNORM for data such as normal maps) with its mip chain, ending in
// SHADER_READ_ONLY_OPTIMAL. Usable after endStaging(batch).
Image uploadTexture(const Device& device, StagingBatch& batch, const Pixels& pixels, VkFormat format);

// A sampler. Textures: LINEAR filtering between texels and mip levels, REPEAT, maxLod
// VK_LOD_CLAMP_NONE. G-buffer attachments, read one texel per pixel: NEAREST (which every depth
// format supports; linear filtering of D32_SFLOAT is optional), CLAMP_TO_EDGE, maxLod 0.
VkSampler createSampler(const Device& device, VkFilter filter, VkSamplerAddressMode addressMode,
                        float maxLod);

}  // namespace common
