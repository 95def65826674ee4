// Image layout transitions: as a VkImageMemoryBarrier2 (synchronization2, introduced in
// chapter-14). Every call site names its stages, accesses and layouts; this only fills in the
// rest of the struct.
#pragma once

#include <vulkan/vulkan.h>

#include "common/vk/device.hpp"  // vk13: the synchronization2 commands

namespace common {

//> barrier
inline VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                                          VkImageLayout newLayout, VkPipelineStageFlags2 srcStage,
                                          VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                                          VkAccessFlags2 dstAccess) {
    return {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = srcStage,
        .srcAccessMask = srcAccess,
        .dstStageMask = dstStage,
        .dstAccessMask = dstAccess,
        .oldLayout = oldLayout,
        .newLayout = newLayout,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS},
    };
}

inline void pipelineBarrier(VkCommandBuffer cmd, const VkImageMemoryBarrier2* barriers, uint32_t count) {
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = count,
        .pImageMemoryBarriers = barriers,
    };
    vk13.CmdPipelineBarrier2(cmd, &dependency);
}
//< barrier

// A layout transition as a Vulkan 1.0 VkImageMemoryBarrier, for vkCmdPipelineBarrier: the helpers
// that chapters 06 and 10 share (texture uploads, screenshots) run on Vulkan 1.1 devices, which may
// lack synchronization2. Array layer 0, mip levels 0 .. mipLevels - 1.
inline VkImageMemoryBarrier layoutBarrier(VkImage image, VkImageAspectFlags aspect, uint32_t mipLevels,
                                          VkImageLayout oldLayout, VkImageLayout newLayout,
                                          VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
    return {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
        .srcAccessMask = srcAccess,
        .dstAccessMask = dstAccess,
        .oldLayout = oldLayout,
        .newLayout = newLayout,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {aspect, 0, mipLevels, 0, 1},
    };
}

}  // namespace common
