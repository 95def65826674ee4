// Command pools, command buffers, fences and semaphores.
#include "common/vk/commands.hpp"

#include <cstdint>

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

VkSemaphore createSemaphore(const Device& device) {
    VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(device.handle, &info, nullptr, &semaphore));
    return semaphore;
}

VkFence createFence(const Device& device, bool signalled) {
    VkFenceCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
        .flags = signalled ? VkFenceCreateFlags{VK_FENCE_CREATE_SIGNALED_BIT} : VkFenceCreateFlags{0},
    };
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(device.handle, &info, nullptr, &fence));
    return fence;
}

std::vector<FrameSync> createFrameSync(const Device& device, uint32_t framesInFlight) {
    std::vector<FrameSync> frames(framesInFlight);
    for (size_t i = 0; i < frames.size(); ++i) {
        FrameSync& frame = frames[i];
        VkCommandPoolCreateInfo poolInfo{
            .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
            .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
            .queueFamilyIndex = device.queueFamily,
        };
        VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &frame.commandPool));
        VkCommandBufferAllocateInfo allocInfo{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = frame.commandPool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = 1,
        };
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &frame.commandBuffer));
        frame.inFlight = createFence(device, true);
        frame.imageAvailable = createSemaphore(device);
        std::string name = "frame " + std::to_string(i);
        nameObject(device.handle, frame.commandPool, name + " commands");
        nameObject(device.handle, frame.commandBuffer, name + " commands");
        nameObject(device.handle, frame.inFlight, name + " in flight");
        nameObject(device.handle, frame.imageAvailable, name + " image available");
    }
    return frames;
}

void destroyFrameSync(const Device& device, std::vector<FrameSync>& frames) {
    for (FrameSync& frame : frames) {
        vkDestroySemaphore(device.handle, frame.imageAvailable, nullptr);
        vkDestroyFence(device.handle, frame.inFlight, nullptr);
        vkDestroyCommandPool(device.handle, frame.commandPool, nullptr);  // frees its command buffer
    }
    frames.clear();
}

VkCommandBuffer beginOneTimeCommands(const Device& device) {
    VkCommandBufferAllocateInfo allocInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = device.oneTimePool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &commandBuffer));
    nameObject(device.handle, commandBuffer, "one-time commands");
    VkCommandBufferBeginInfo beginInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(commandBuffer, &beginInfo));
    return commandBuffer;
}

void submitOneTimeCommands(const Device& device, VkCommandBuffer commandBuffer) {
    VK_CHECK(vkEndCommandBuffer(commandBuffer));
    VkFence done = createFence(device, false);
    nameObject(device.handle, done, "one-time commands done");
    VkSubmitInfo submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .commandBufferCount = 1,
        .pCommandBuffers = &commandBuffer,
    };
    VK_CHECK(vkQueueSubmit(device.queue, 1, &submit, done));
    VK_CHECK(vkWaitForFences(device.handle, 1, &done, VK_TRUE, UINT64_MAX));
    vkDestroyFence(device.handle, done, nullptr);
    vkFreeCommandBuffers(device.handle, device.oneTimePool, 1, &commandBuffer);
}

}  // namespace common
