// chapter-06: buffers.
#include "buffer.hpp"

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

//> find-memory-type
// A device offers a few memory heaps (device-local video memory, system memory the GPU can
// reach) and several memory types on them, each with properties: DEVICE_LOCAL (fast for the
// GPU), HOST_VISIBLE (the CPU can map it), HOST_COHERENT (CPU writes need no explicit flush).
// A buffer's requirements say which types it may live in, as bits of `typeBits`; of those we
// take the first that has everything we ask for (drivers list the best types first).
uint32_t findMemoryType(const common::Device& device, uint32_t typeBits, VkMemoryPropertyFlags required) {
    const VkPhysicalDeviceMemoryProperties& memory = device.memory;  // vkGetPhysicalDeviceMemoryProperties
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required) return i;
    throw common::Failure("no Vulkan memory type has the properties this buffer needs");
}
//< find-memory-type

//> create-buffer
Buffer createBuffer(const common::Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name) {
    Buffer buffer;
    buffer.size = size;
    // The buffer object itself: its size, what it will be used for (vertex data, index data, a
    // copy source...) and that one queue family at a time uses it.
    VkBufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VK_CHECK(vkCreateBuffer(device.handle, &info, nullptr, &buffer.handle));
    // Its name, for graphics debuggers and validation messages (VK_EXT_debug_utils, where the
    // instance has it: common/vk/debug_names.hpp). Every object our code creates gets one.
    common::nameObject(device.handle, buffer.handle, name);

    // It has no memory yet. The driver says how much it needs (maybe more than `size`, for
    // alignment) and in which memory types.
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle, buffer.handle, &requirements);

    // SHORTCUT: one allocation per buffer, as the book does. A real engine sub-allocates large
    // blocks (e.g. with the Vulkan Memory Allocator); maxMemoryAllocationCount can be as low as 4096.
    VkMemoryAllocateInfo allocInfo{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = requirements.size,
        .memoryTypeIndex = findMemoryType(device, requirements.memoryTypeBits, memoryFlags),
    };
    VK_CHECK(vkAllocateMemory(device.handle, &allocInfo, nullptr, &buffer.memory));
    common::nameObject(device.handle, buffer.memory, name);
    VK_CHECK(vkBindBufferMemory(device.handle, buffer.handle, buffer.memory, 0));  // at offset 0

    // Memory the CPU can see is mapped once and stays mapped: the pointer is valid until the
    // memory is freed, and mapping it again for every write would only cost time.
    if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VK_CHECK(vkMapMemory(device.handle, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
    return buffer;
}

void destroyBuffer(const common::Device& device, Buffer& buffer) {
    vkDestroyBuffer(device.handle, buffer.handle, nullptr);
    vkFreeMemory(device.handle, buffer.memory, nullptr);  // freeing mapped memory unmaps it
    buffer = {};
}
//< create-buffer
