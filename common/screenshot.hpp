// Reads colour images back from the GPU: as an 8-bit RGB PNG (--screenshot), or as floats (to
// check a light pass's output for NaN, infinities and negative values).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/device.hpp"

namespace common {

// `image` is in `layout` and stays in it. The bytes are written as stored: with an _SRGB format
// they are already sRGB-encoded, which is what a PNG holds. BGRA and RGBA 8-bit formats are
// swizzled to RGB; alpha is dropped (a presented image is opaque). The PNG goes to a
// temporary file first and is renamed over `path`, so a failure never leaves half a file.
void saveScreenshot(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                    VkImageLayout layout, const std::filesystem::path& path);

// The texels of a 2D colour image, tightly packed, after all earlier work on the queue. `image`
// is in `layout` and stays in it.
std::vector<uint8_t> readImage(const Device& device, VkImage image, VkExtent2D extent, VkImageLayout layout,
                               uint32_t bytesPerTexel, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

// An R32G32B32A32_SFLOAT or R16G16B16A16_SFLOAT image as 4 floats per texel; an R16G16_UNORM or
// D32_SFLOAT image in the first 2 or 1 of the 4.
std::vector<float> readFloatImage(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                                  VkImageLayout layout);

// Writes 4-float texels (as readFloatImage returns them) as a Portable Float Map: channels 3
// ("PF", RGB) or 1 ("Pf", the R channel only). Rows go bottom to top, as the format says.
void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba, int channels, int firstChannel = 0);

}  // namespace common
