// Image and image view creation.
#include "common/vk/image.hpp"

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/memory.hpp"

namespace common {

VkImageView createImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect,
                            uint32_t mipLevels, VkImageViewType type, uint32_t layers) {
    VkImageViewCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = type,
        .format = format,
        .subresourceRange = {.aspectMask = aspect,
                             .baseMipLevel = 0,
                             .levelCount = mipLevels,
                             .baseArrayLayer = 0,
                             .layerCount = layers},
    };
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device.handle, &info, nullptr, &view));
    return view;
}

namespace {

// createImage and createLayeredImage: the image, its memory, its view. They differ only in the
// array layers and the view's type.
Image makeImage(const Device& device, VkExtent2D extent, uint32_t layers, VkImageViewType viewType,
                VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, const std::string& name,
                uint32_t mipLevels, VkImageCreateFlags flags, const void* next) {
    Image image;
    image.mipLevels = mipLevels;
    image.layers = layers;
    image.format = format;
    image.extent = extent;
    //> layered-image
    VkImageCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .pNext = next,
        .flags = flags,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {extent.width, extent.height, 1},
        .mipLevels = mipLevels,
        .arrayLayers = layers,  // chapter-16's shadow map: a layer per cascade
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
    image.memory = allocateMemory(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    VK_CHECK(vkBindImageMemory(device.handle, image.handle, image.memory, 0));
    // A layered image gets a 2D_ARRAY view over all its layers: what a sampler2DArray reads and a
    // layered pass draws into (the other images, a 2D view).
    image.view = createImageView(device, image.handle, format, aspect, mipLevels, viewType, layers);
    //< layered-image
    nameObject(device.handle, image.view, name);
    return image;
}

}  // namespace

Image createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, const std::string& name, uint32_t mipLevels,
                  VkImageCreateFlags flags, const void* next) {
    return makeImage(device, extent, 1, VK_IMAGE_VIEW_TYPE_2D, format, usage, aspect, name, mipLevels, flags,
                     next);
}

Image createLayeredImage(const Device& device, VkExtent2D extent, uint32_t layers, VkFormat format,
                         VkImageUsageFlags usage, VkImageAspectFlags aspect, const std::string& name) {
    return makeImage(device, extent, layers, VK_IMAGE_VIEW_TYPE_2D_ARRAY, format, usage, aspect, name, 1, 0,
                     nullptr);
}

void destroyImage(const Device& device, Image& image) {
    vkDestroyImageView(device.handle, image.view, nullptr);
    vkDestroyImage(device.handle, image.handle, nullptr);
    vkFreeMemory(device.handle, image.memory, nullptr);
    image = {};
}

}  // namespace common
