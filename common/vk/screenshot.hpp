// Reads colour images back from the GPU: as an 8-bit RGB PNG (--screenshot), or as floats (to
// check a light pass's output for NaN, infinities and negative values).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/vk/device.hpp"

namespace common {

// `image` is in `layout` and stays in it. The values are written as stored: they are already
// sRGB-encoded (by the hardware for an _SRGB format, by our shaders for a _UNORM one), which is
// what a PNG holds. BGRA and RGBA 8-bit formats are swizzled to RGB, the 10-bit A2R10G10B10 and
// A2B10G10R10 ones rounded to 8 bits; alpha is dropped (a presented image is opaque). The PNG goes to a
// temporary file first and is renamed over `path`, so a failure never leaves half a file.
void saveScreenshot(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                    VkImageLayout layout, const std::filesystem::path& path);

// The texels of a 2D colour image, tightly packed, after all earlier work on the queue. `image`
// is in `layout` and stays in it.
std::vector<uint8_t> readImage(const Device& device, VkImage image, VkExtent2D extent, VkImageLayout layout,
                               uint32_t bytesPerTexel, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

// An R32G32B32A32_SFLOAT or R16G16B16A16_SFLOAT image as 4 floats per texel; an R16G16_UNORM,
// D32_SFLOAT or X8_D24_UNORM_PACK32 image in the first 2 or 1 of the 4.
std::vector<float> readFloatImage(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                                  VkImageLayout layout);

// Writes 4-float texels (as readFloatImage returns them) as a Portable Float Map: channels 3
// ("PF", RGB) or 1 ("Pf", the R channel only). Rows go bottom to top, as the format says.
void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba, int channels, int firstChannel = 0);

}  // namespace common
