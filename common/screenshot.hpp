// Reads a colour image back from the GPU and writes it as an 8-bit RGB PNG.
#pragma once

#include <vulkan/vulkan.h>

#include <filesystem>

#include "common/device.hpp"

namespace common {

// `image` is in `layout` and stays in it. The bytes are written as stored: with an _SRGB format
// they are already sRGB-encoded, which is what a PNG holds. BGRA and RGBA 8-bit formats are
// swizzled to RGB; alpha is dropped (a presented image is opaque). The PNG goes to a
// temporary file first and is renamed over `path`, so a failure never leaves half a file.
void saveScreenshot(const Device& device, VkImage image, VkFormat format, VkExtent2D extent,
                    VkImageLayout layout, const std::filesystem::path& path);

}  // namespace common
