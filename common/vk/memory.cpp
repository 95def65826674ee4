// Memory types and allocations (common/vk/memory.hpp).
#include "common/vk/memory.hpp"

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

uint32_t findMemoryType(const Device& device, uint32_t typeBits, VkMemoryPropertyFlags required) {
    for (uint32_t i = 0; i < device.memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (device.memory.memoryTypes[i].propertyFlags & required) == required)
            return i;
    throw Failure("no Vulkan memory type has the properties this resource needs");
}

VkDeviceMemory allocateMemory(const Device& device, const VkMemoryRequirements& requirements,
                              VkMemoryPropertyFlags flags, const std::string& name,
                              VkMemoryAllocateFlags allocateFlags) {
    // SHORTCUT: one allocation per buffer or image, as the book does. A real engine sub-allocates
    // large blocks (e.g. with the Vulkan Memory Allocator); maxMemoryAllocationCount can be as low
    // as 4096.
    // A buffer read through its device address needs memory allocated with that flag (chapter-18):
    // any memory type, no dedicated allocation.
    VkMemoryAllocateFlagsInfo flagsInfo{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO,
                                        .flags = allocateFlags};
    VkMemoryAllocateInfo allocInfo{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .pNext = allocateFlags != 0 ? &flagsInfo : nullptr,
        .allocationSize = requirements.size,
        .memoryTypeIndex = findMemoryType(device, requirements.memoryTypeBits, flags),
    };
    VkDeviceMemory memory = VK_NULL_HANDLE;
    // VK_CHECK's report, naming the resource: which allocation ran out is what a reader needs.
    if (VkResult result = vkAllocateMemory(device.handle, &allocInfo, nullptr, &memory); result != VK_SUCCESS)
        throwVkError(result, ("vkAllocateMemory for \"" + name + "\"").c_str(), __FILE__, __LINE__);
    nameObject(device.handle, memory, name);
    return memory;
}

}  // namespace common
