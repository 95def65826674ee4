// Physical device selection, the logical device, its graphics queue and a command pool for
// one-time work (uploads, screenshots). The book's PhysicalDevice, Device and Queue (chapter 3).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

#include "common/instance.hpp"

namespace common {

struct Device {
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    std::string driver;               // driver name and version, e.g. "llvmpipe, Mesa 22.3.6"
    uint32_t timestampValidBits = 0;  // of the queue family; 0: no timestamps
    VkPhysicalDeviceMemoryProperties memory{};
    VkDevice handle = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics, and present when there is a surface
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool oneTimePool = VK_NULL_HANDLE;  // transient command buffers: beginOneTimeCommands()
};

// Optional features a chapter needs; a device without one of them is not chosen.
struct DeviceFeatures {
    bool dynamicRendering = false;   // chapter-14 on: vkCmdBeginRendering instead of render passes
    bool synchronization2 = false;   // chapter-14 on: vkCmdPipelineBarrier2, vkQueueSubmit2
    bool scalarBlockLayout = false;  // chapter-15: C-like struct layout in storage buffers
    bool maintenance4 = false;       // compute shaders: glslang's SPIR-V 1.6 declares LocalSizeId
};

// Picks a device with Vulkan 1.3 and a graphics queue (that can also present to `surface`, when
// there is one), preferring discrete > integrated > virtual > CPU. `nameFilter`, when not empty,
// selects by case-insensitive substring of the device name; no match is an InputError that lists
// the devices there are.
Device createDevice(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter,
                    const DeviceFeatures& features = {});
void destroyDevice(Device& device);

}  // namespace common
