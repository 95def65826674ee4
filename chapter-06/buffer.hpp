// chapter-06: buffers -- the book's VulkanBuffer: a VkBuffer, the memory behind it (of a type
// chosen from what the buffer allows and what we need), bound, and mapped when the CPU writes it.
//
// Deliberate repetition: common/vk/buffer.cpp holds the same code for the later chapters, which
// use it without spelling it out again. This chapter introduces it, so here it is written out.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include <cstdint>

#include "common/vk/device.hpp"

// The book's VulkanBuffer.
struct Buffer {
    VkBuffer handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // set when the memory is host-visible: mapped for the buffer's whole life
};

// The index of the first memory type that `typeBits` allows and that has every property in
// `required`; throws common::Failure when there is none.
uint32_t findMemoryType(const common::Device& device, uint32_t typeBits, VkMemoryPropertyFlags required);

// `name`: what a graphics debugger and validation messages call the buffer and its memory.
Buffer createBuffer(const common::Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name);
void destroyBuffer(const common::Device& device, Buffer& buffer);
