// Names and labels for graphics debuggers (RenderDoc, Nsight) and validation messages, through
// VK_EXT_debug_utils: every object our code creates gets a name where it is created, and every
// pass a label with the name of its benchmark row. The instance enables the extension wherever
// it is offered (common/vk/instance.cpp); where it is not, every call here returns at once.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <type_traits>

namespace common {

// The extension's functions for this instance, or none (then names and labels are skipped).
void loadDebugNames(VkInstance instance, bool enabled);
bool debugNamesEnabled();

// Hands the name to the driver and the layers, which keep it with the object (and forget it when
// the object is destroyed); nothing is kept here, so nothing grows with reloads and resizes, and
// a handle the driver reuses gets the name its new object is given where it is made.
void setObjectName(VkDevice device, VkObjectType type, uint64_t handle, const std::string& name);

// The object type of each handle type we name.
template <typename Handle>
constexpr VkObjectType objectType() {
    if constexpr (std::is_same_v<Handle, VkBuffer>)
        return VK_OBJECT_TYPE_BUFFER;
    else if constexpr (std::is_same_v<Handle, VkImage>)
        return VK_OBJECT_TYPE_IMAGE;
    else if constexpr (std::is_same_v<Handle, VkImageView>)
        return VK_OBJECT_TYPE_IMAGE_VIEW;
    else if constexpr (std::is_same_v<Handle, VkDeviceMemory>)
        return VK_OBJECT_TYPE_DEVICE_MEMORY;
    else if constexpr (std::is_same_v<Handle, VkSampler>)
        return VK_OBJECT_TYPE_SAMPLER;
    else if constexpr (std::is_same_v<Handle, VkShaderModule>)
        return VK_OBJECT_TYPE_SHADER_MODULE;
    else if constexpr (std::is_same_v<Handle, VkPipeline>)
        return VK_OBJECT_TYPE_PIPELINE;
    else if constexpr (std::is_same_v<Handle, VkPipelineLayout>)
        return VK_OBJECT_TYPE_PIPELINE_LAYOUT;
    else if constexpr (std::is_same_v<Handle, VkPipelineCache>)
        return VK_OBJECT_TYPE_PIPELINE_CACHE;
    else if constexpr (std::is_same_v<Handle, VkRenderPass>)
        return VK_OBJECT_TYPE_RENDER_PASS;
    else if constexpr (std::is_same_v<Handle, VkFramebuffer>)
        return VK_OBJECT_TYPE_FRAMEBUFFER;
    else if constexpr (std::is_same_v<Handle, VkDescriptorSetLayout>)
        return VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT;
    else if constexpr (std::is_same_v<Handle, VkDescriptorPool>)
        return VK_OBJECT_TYPE_DESCRIPTOR_POOL;
    else if constexpr (std::is_same_v<Handle, VkDescriptorSet>)
        return VK_OBJECT_TYPE_DESCRIPTOR_SET;
    else if constexpr (std::is_same_v<Handle, VkCommandPool>)
        return VK_OBJECT_TYPE_COMMAND_POOL;
    else if constexpr (std::is_same_v<Handle, VkCommandBuffer>)
        return VK_OBJECT_TYPE_COMMAND_BUFFER;
    else if constexpr (std::is_same_v<Handle, VkFence>)
        return VK_OBJECT_TYPE_FENCE;
    else if constexpr (std::is_same_v<Handle, VkSemaphore>)
        return VK_OBJECT_TYPE_SEMAPHORE;
    else if constexpr (std::is_same_v<Handle, VkQueryPool>)
        return VK_OBJECT_TYPE_QUERY_POOL;
    else if constexpr (std::is_same_v<Handle, VkSwapchainKHR>)
        return VK_OBJECT_TYPE_SWAPCHAIN_KHR;
    else if constexpr (std::is_same_v<Handle, VkQueue>)
        return VK_OBJECT_TYPE_QUEUE;
    else
        static_assert(sizeof(Handle) == 0, "a handle type nameObject does not know");
}

// nameObject(device, image, "G-buffer albedo"): the name a debugger and the validation layer show.
template <typename Handle>
void nameObject(VkDevice device, Handle handle, const std::string& name) {
    if (!debugNamesEnabled() || handle == VK_NULL_HANDLE) return;
    setObjectName(device, objectType<Handle>(), reinterpret_cast<uint64_t>(handle), name);
}

// A labelled region of a command buffer: a pass, as a debugger's event list shows it.
void beginLabel(VkCommandBuffer cmd, const std::string& name);
void endLabel(VkCommandBuffer cmd);

}  // namespace common
