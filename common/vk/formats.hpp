// What our code knows about the formats of the images it presents and of its depth buffers: a
// presented image may come in whatever format the window system offers (8-bit sRGB or UNORM,
// 10-bit UNORM on a 30-bit desktop), and a depth buffer in whatever format the device can render
// to. One place decides, for every chapter: which formats we can draw to and read back, whether
// the hardware sRGB-encodes what a shader writes, and which depth format a device gets.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "common/vk/device.hpp"

namespace common {

// The formats a presented image may have that we can draw to and write as a PNG, in the order a
// window takes them when it offers several: 8-bit sRGB (the hardware encodes), 8-bit UNORM and
// 10-bit UNORM (our shaders encode). Their names are --target-format's values.
inline constexpr std::array<VkFormat, 6> kPresentFormats = {VK_FORMAT_B8G8R8A8_SRGB,
                                                            VK_FORMAT_R8G8B8A8_SRGB,
                                                            VK_FORMAT_B8G8R8A8_UNORM,
                                                            VK_FORMAT_R8G8B8A8_UNORM,
                                                            VK_FORMAT_A2R10G10B10_UNORM_PACK32,
                                                            VK_FORMAT_A2B10G10R10_UNORM_PACK32};

// "B8G8R8A8_SRGB", "A2R10G10B10_UNORM_PACK32", ... (a number for a format we do not name).
std::string formatName(VkFormat format);
std::string colorSpaceName(VkColorSpaceKHR colorSpace);
// --target-format's value (case-insensitive, the _PACK32 suffix optional) to a present format.
std::optional<VkFormat> presentFormatByName(std::string_view name);
// "B8G8R8A8_SRGB|R8G8B8A8_SRGB|..." for messages and --help.
std::string presentFormatNames();

// True when the hardware sRGB-encodes what a shader writes to an image of this format (the
// _SRGB formats). Every pass that writes a presented image of another format encodes itself.
bool encodesSrgb(VkFormat format);
// The same memory read without the hardware's sRGB conversion (B8G8R8A8_SRGB -> B8G8R8A8_UNORM);
// the format itself for a format that has none.
VkFormat withoutSrgb(VkFormat format);

// The sRGB transfer function (IEC 61966-2-1), for a colour the CPU hands to a UNORM image (a
// clear colour); shaders use shaders/include/srgb.glsl.
float encodeSrgb(float linear);

// The depth format a chapter renders with: D32_SFLOAT where the device can render to it and sample
// it, else X8_D24_UNORM_PACK32 (the specification guarantees depth attachments of one of the two;
// we also need to sample it).
// `needFloat`: only D32_SFLOAT will do (reversed-Z); a device without it is refused in one line
// that names `why`.
VkFormat chooseDepthFormat(const Device& device, bool needFloat = false, const char* why = nullptr);

}  // namespace common
