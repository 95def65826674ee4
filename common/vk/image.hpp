// 2D images with their own memory, and image views. The book's Image and ImageView
// (chapters 4 and 8); here also the colour images of the headless target.
#pragma once

#include <vulkan/vulkan.h>

#include "common/vk/device.hpp"

namespace common {

struct Image {
    VkImage handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t mipLevels = 1;
};

VkImageView createImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect,
                            uint32_t mipLevels = 1);

// A device-local 2D image, one layer, optimal tiling, with a view of `aspect` over all its mip levels.
// `flags`: e.g. MUTABLE_FORMAT, for an image also viewed in another format of the same size;
// `next`: what VkImageCreateInfo chains (the list of those formats).
// `name`: what graphics debuggers and validation messages call it (common/vk/debug_names.hpp).
Image createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, const std::string& name, uint32_t mipLevels = 1,
                  VkImageCreateFlags flags = 0, const void* next = nullptr);
void destroyImage(const Device& device, Image& image);

}  // namespace common
