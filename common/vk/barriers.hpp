// One image layout transition as a VkImageMemoryBarrier2 (synchronization2, introduced in
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

}  // namespace common
