// Physical device selection, the logical device, its graphics queue and a command pool for
// one-time work (uploads, screenshots). The book's PhysicalDevice, Device and Queue (chapter 3).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/vk/instance.hpp"

namespace common {

struct Device {
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    uint32_t apiVersion = 0;          // what the device offers (properties.apiVersion)
    std::string driver;               // driver name and version, e.g. "llvmpipe, Mesa 22.3.6"
    std::string features;             // where the chapter's features come from, for reports
    uint32_t timestampValidBits = 0;  // of the queue family; 0: no timestamps
    VkPhysicalDeviceMemoryProperties memory{};
    VkDevice handle = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics, and present when there is a surface
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool oneTimePool = VK_NULL_HANDLE;  // transient command buffers: beginOneTimeCommands()
    // VK_KHR_swapchain_mutable_format is enabled: a swapchain's _SRGB images can also be viewed
    // as _UNORM (the GUI pass draws through such views).
    bool swapchainMutableFormat = false;
    // VK_EXT_swapchain_maintenance1 is enabled: a present can signal a fence when the
    // presentation engine is done with what it used (common/wnd/target.cpp retires old swapchains so).
    bool swapchainMaintenance1 = false;
    // depthClamp is enabled (DeviceFeatures::depthClampWhereAvailable and the device has it).
    bool depthClamp = false;
    // Pipelines a live reload replaced while frames in flight may still use them, each with the
    // frame before which it was last used (common/vk/pipeline.hpp: swapPipelines retires them,
    // releaseRetiredPipelines destroys them once those frames are done, destroyDevice the rest).
    struct RetiredPipeline {
        VkPipeline pipeline = VK_NULL_HANDLE;
        uint64_t frame = 0;
    };
    std::vector<RetiredPipeline> retiredPipelines;
};

// Optional features a chapter needs; a device without one of them is not chosen.
struct DeviceFeatures {
    // The oldest Vulkan version whose core the chapter's calls stay within. Chapters 06 and 10
    // need 1.1 (a negative viewport height flips y); chapter-14 on asks for 1.2 with the features
    // below, which Vulkan 1.3 has in its core and a 1.2 device may offer as extensions.
    uint32_t minApiVersion = VK_API_VERSION_1_1;
    bool dynamicRendering = false;          // chapter-14 on: vkCmdBeginRendering instead of render passes
    bool synchronization2 = false;          // chapter-14 on: vkCmdPipelineBarrier2, vkQueueSubmit2
    bool scalarBlockLayout = false;         // chapter-15: C-like struct layout in storage buffers (core 1.2)
    bool geometryShader = false;            // chapter-16: the shadow pass sends triangles to every cascade
    bool depthClampWhereAvailable = false;  // chapter-16: enabled when the device has it (Device::depthClamp)
    bool multiview = false;                 // chapter-15-lab's shadow study: a view per cascade (core 1.1)
    bool vertexStores = false;      // chapter-15-lab's skinning study: a vertex shader writes a buffer
    bool preciseOcclusion = false;  // chapter-15-lab's skinning study: exact occlusion query counts
    // chapter-18 on: shaders read buffers through 64-bit pointers (core 1.2, shaderInt64 core 1.0).
    bool bufferDeviceAddress = false;
    // chapter-19 on: a vkCmdDrawIndirect of many commands (multiDrawIndirect), each with its own
    // firstInstance (drawIndirectFirstInstance); both core 1.0 features.
    bool indirectDrawing = false;
};

// The commands of dynamic rendering and synchronization2. A Vulkan 1.3 device has them in its
// core (vkCmdBeginRendering ...); a 1.2 device has the same commands under the names of its
// extensions VK_KHR_dynamic_rendering and VK_KHR_synchronization2 (vkCmdBeginRenderingKHR ...),
// which the core of 1.2 does not export. createDevice points these at whichever the device has,
// so chapter-14 on calls common::vk13.CmdBeginRendering(...) on either. Null until then.
struct Vulkan13Commands {
    PFN_vkCmdBeginRendering CmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering CmdEndRendering = nullptr;
    PFN_vkCmdPipelineBarrier2 CmdPipelineBarrier2 = nullptr;
    PFN_vkQueueSubmit2 QueueSubmit2 = nullptr;
};
// One device per process, so one table (as the volk loader keeps one); set by createDevice.
extern Vulkan13Commands vk13;

// Picks a device that has the Vulkan version and `features` the chapter asks for and a graphics
// queue (that can also present to `surface`, when there is one), preferring discrete > integrated
// > virtual > CPU. `nameFilter`, when not empty, selects by case-insensitive substring of the
// device name; no match is an InputError that lists the devices there are. A device that cannot
// be used is refused in one line naming what it lacks.
Device createDevice(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter,
                    const DeviceFeatures& features = {});
void destroyDevice(Device& device);

}  // namespace common
