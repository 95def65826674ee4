// 2D images with their own memory, and image views. The book's Image and ImageView
// (chapters 4 and 8); here also the colour images of the headless target.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "common/vk/device.hpp"

namespace common {

struct Image {
    VkImage handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t mipLevels = 1;
    uint32_t layers = 1;
};

// A view of `aspect` over mip levels 0 .. mipLevels - 1 and array layers 0 .. layers - 1.
VkImageView createImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect,
                            uint32_t mipLevels = 1, VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D,
                            uint32_t layers = 1);

// A device-local 2D image, one layer, optimal tiling, with a view of `aspect` over all its mip levels.
// `flags`: e.g. MUTABLE_FORMAT, for an image also viewed in another format of the same size;
// `next`: what VkImageCreateInfo chains (the list of those formats).
// `name`: what graphics debuggers and validation messages call it (common/vk/debug_names.hpp).
Image createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, const std::string& name, uint32_t mipLevels = 1,
                  VkImageCreateFlags flags = 0, const void* next = nullptr);
// A device-local 2D image of `layers` array layers and a 2D_ARRAY view over all of them (a shader
// reads it as a sampler2DArray; a layered render target draws into every layer): chapter-16's
// shadow map, a layer per cascade.
Image createLayeredImage(const Device& device, VkExtent2D extent, uint32_t layers, VkFormat format,
                         VkImageUsageFlags usage, VkImageAspectFlags aspect, const std::string& name);
void destroyImage(const Device& device, Image& image);

}  // namespace common
