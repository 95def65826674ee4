// Image and image view creation.
#include "common/vk/image.hpp"

#include "common/core/check.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

VkImageView createImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect,
                            uint32_t mipLevels) {
    VkImageViewCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = {.aspectMask = aspect,
                             .baseMipLevel = 0,
                             .levelCount = mipLevels,
                             .baseArrayLayer = 0,
                             .layerCount = 1},
    };
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device.handle, &info, nullptr, &view));
    return view;
}

Image createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, const std::string& name, uint32_t mipLevels,
                  VkImageCreateFlags flags, const void* next) {
    Image image;
    image.mipLevels = mipLevels;
    image.format = format;
    image.extent = extent;
    VkImageCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .pNext = next,
        .flags = flags,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {extent.width, extent.height, 1},
        .mipLevels = mipLevels,
        .arrayLayers = 1,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    VK_CHECK(vkCreateImage(device.handle, &info, nullptr, &image.handle));
    nameObject(device.handle, image.handle, name);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device.handle, image.handle, &requirements);
    VkMemoryAllocateInfo allocInfo{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = requirements.size,
        .memoryTypeIndex =
            findMemoryType(device, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
    };
    VK_CHECK(vkAllocateMemory(device.handle, &allocInfo, nullptr, &image.memory));
    nameObject(device.handle, image.memory, name);
    VK_CHECK(vkBindImageMemory(device.handle, image.handle, image.memory, 0));
    image.view = createImageView(device, image.handle, format, aspect, mipLevels);
    nameObject(device.handle, image.view, name);
    return image;
}

void destroyImage(const Device& device, Image& image) {
    vkDestroyImageView(device.handle, image.view, nullptr);
    vkDestroyImage(device.handle, image.handle, nullptr);
    vkFreeMemory(device.handle, image.memory, nullptr);
    image = {};
}

}  // namespace common
