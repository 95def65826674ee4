// 2D images with their own memory, and image views. The book's Image and ImageView
// (chapters 4 and 8); here also the colour images of the headless target.
#pragma once

#include <vulkan/vulkan.h>

#include "common/device.hpp"

namespace common {

struct Image {
    VkImage handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
};

VkImageView createImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect);

// A device-local 2D image, one mip level, one layer, optimal tiling, with a view of `aspect`.
Image createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect);
void destroyImage(const Device& device, Image& image);

}  // namespace common
