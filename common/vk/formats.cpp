// Present and depth formats.
#include "common/vk/formats.hpp"

#include <cctype>
#include <cmath>

#include "common/core/check.hpp"

namespace common {

std::string formatName(VkFormat format) {
    switch (format) {
        case VK_FORMAT_B8G8R8A8_SRGB:
            return "B8G8R8A8_SRGB";
        case VK_FORMAT_R8G8B8A8_SRGB:
            return "R8G8B8A8_SRGB";
        case VK_FORMAT_B8G8R8A8_UNORM:
            return "B8G8R8A8_UNORM";
        case VK_FORMAT_R8G8B8A8_UNORM:
            return "R8G8B8A8_UNORM";
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32:
            return "A2R10G10B10_UNORM_PACK32";
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            return "A2B10G10R10_UNORM_PACK32";
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_D32_SFLOAT:
            return "D32_SFLOAT";
        case VK_FORMAT_X8_D24_UNORM_PACK32:
            return "X8_D24_UNORM_PACK32";
        default:
            return std::string("format ").append(std::to_string(int(format)));
    }
}

std::string colorSpaceName(VkColorSpaceKHR colorSpace) {
    if (colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return "SRGB_NONLINEAR";
    return std::string("colour space ").append(std::to_string(int(colorSpace)));
}

std::optional<VkFormat> presentFormatByName(std::string_view name) {
    std::string upper(name);
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (VkFormat format : kPresentFormats) {
        std::string full = formatName(format);
        if (upper == full || (full.ends_with("_PACK32") && upper + "_PACK32" == full)) return format;
    }
    return std::nullopt;
}

std::string presentFormatNames() {
    std::string names;
    for (VkFormat format : kPresentFormats) {
        if (!names.empty()) names += '|';
        names += formatName(format);
    }
    return names;
}

bool encodesSrgb(VkFormat format) {
    return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB ||
           format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

VkFormat withoutSrgb(VkFormat format) {
    switch (format) {
        case VK_FORMAT_B8G8R8A8_SRGB:
            return VK_FORMAT_B8G8R8A8_UNORM;
        case VK_FORMAT_R8G8B8A8_SRGB:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
            return VK_FORMAT_A8B8G8R8_UNORM_PACK32;
        default:
            return format;
    }
}

float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

VkFormat chooseDepthFormat(const Device& device, bool needFloat, const char* why) {
    constexpr VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32}) {
        if (needFloat && format != VK_FORMAT_D32_SFLOAT) break;
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
        if ((properties.optimalTilingFeatures & needed) == needed) return format;
    }
    if (needFloat)
        throw Failure(std::string(why ? why : "this chapter") +
                      " needs D32_SFLOAT depth, which this device cannot render to and sample");
    throw Failure("the device can render to and sample neither D32_SFLOAT nor X8_D24_UNORM_PACK32 depth");
}

}  // namespace common
