// Device memory for buffers and images: the memory type that has the properties a resource needs,
// and one allocation for it (the book's VkUtils.memoryTypeFromProperties and the allocation in its
// VkBuffer and Image, chapters 5 and 6; chapter-06/buffer.cpp writes them out).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "common/vk/device.hpp"

namespace common {

// The first memory type allowed by `typeBits` that has all of `required`; throws if none.
uint32_t findMemoryType(const Device& device, uint32_t typeBits, VkMemoryPropertyFlags required);
// Memory for one buffer or image, of a type with `flags` that `requirements` allows, named `name`
// (chapter-06/buffer.cpp writes the same out). The caller binds it.
// `allocateFlags`: VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT for a buffer whose address shaders read
// (chapter-18 on).
VkDeviceMemory allocateMemory(const Device& device, const VkMemoryRequirements& requirements,
                              VkMemoryPropertyFlags flags, const std::string& name,
                              VkMemoryAllocateFlags allocateFlags = 0);

}  // namespace common
