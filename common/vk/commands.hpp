// Command buffers and the per-frame synchronisation objects of frames in flight.
// The book's CommandPool, CommandBuffer, Fence and Semaphore (chapters 4-5).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "common/vk/device.hpp"

namespace common {

// What one frame in flight owns: its command pool and buffer (re-recorded every frame, so the
// pool is reset as a whole), the fence that says the GPU is done with them, and the semaphore
// that the target signals when the image to draw into is ready. The semaphore signalled when
// drawing is done belongs to the image, not the frame (see Target::renderFinished).
struct FrameSync {
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VkFence inFlight = VK_NULL_HANDLE;  // created signalled: the first wait returns at once
    VkSemaphore imageAvailable = VK_NULL_HANDLE;
};

std::vector<FrameSync> createFrameSync(const Device& device, uint32_t framesInFlight);
void destroyFrameSync(const Device& device, std::vector<FrameSync>& frames);

VkSemaphore createSemaphore(const Device& device);
VkFence createFence(const Device& device, bool signalled);

// A primary command buffer from the device's transient pool, begun for one submission.
VkCommandBuffer beginOneTimeCommands(const Device& device);
// Ends, submits, waits for completion and frees it.
void submitOneTimeCommands(const Device& device, VkCommandBuffer commandBuffer);

}  // namespace common
