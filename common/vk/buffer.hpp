// Buffers, memory-type selection and the book's staging upload: every copy of a batch recorded
// into one command buffer, submitted once, waited for once. The book's VulkanBuffer and
// VulkanMesh.loadMeshes (chapter 6).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "common/vk/device.hpp"
#include "common/vk/memory.hpp"

namespace common {

struct Buffer {
    VkBuffer handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // persistently mapped when the memory is host-visible
    // Where shaders find it (chapter-18 on): for a buffer made with
    // VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, vkGetBufferDeviceAddress's answer; else 0.
    VkDeviceAddress address = 0;
};

// `name`: what graphics debuggers and validation messages call it (common/vk/debug_names.hpp).
Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name);
void destroyBuffer(const Device& device, Buffer& buffer);

// A batch of uploads to device-local buffers through host-visible staging buffers.
struct StagingBatch {
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    std::vector<Buffer> stagingBuffers;  // freed by endStaging once the copies are done
};

StagingBatch beginStaging(const Device& device);
// Copies `size` bytes into a new staging buffer and records its copy into a new device-local
// buffer of the given usage (TRANSFER_DST is added). The returned buffer is usable after endStaging.
Buffer uploadStaged(const Device& device, StagingBatch& batch, const void* data, VkDeviceSize size,
                    VkBufferUsageFlags usage, const std::string& name);
// Submits the batch, waits for it, and frees the staging buffers.
void endStaging(const Device& device, StagingBatch& batch);

}  // namespace common
