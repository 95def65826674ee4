// Physical device selection, the logical device, its graphics queue and a command pool for
// one-time work (uploads, screenshots). The book's PhysicalDevice, Device and Queue (chapter 3).
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

#include "common/instance.hpp"

namespace common {

struct Device {
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    VkDevice handle = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics, and present when there is a surface
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool oneTimePool = VK_NULL_HANDLE;  // transient command buffers: beginOneTimeCommands()
};

// Picks a device with Vulkan 1.3 and a graphics queue (that can also present to `surface`, when
// there is one), preferring discrete > integrated > virtual > CPU. `nameFilter`, when not empty,
// selects by case-insensitive substring of the device name; no match is an InputError that lists
// the devices there are.
Device createDevice(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter);
void destroyDevice(Device& device);

}  // namespace common
