// Descriptor set layouts, pools, sets and their updates: thin helpers over the calls the book
// wraps in DescriptorSetLayout, DescriptorPool and DescriptorSet (its chapter 9).
#pragma once

#include <vulkan/vulkan.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "common/vk/device.hpp"

namespace common {

// One binding of `count` descriptors of `type`, visible to `stages`.
VkDescriptorSetLayoutBinding binding(uint32_t index, VkDescriptorType type, VkShaderStageFlags stages,
                                     uint32_t count = 1);
// `name`: what graphics debuggers and validation messages call it (common/vk/debug_names.hpp).
VkDescriptorSetLayout createDescriptorSetLayout(const Device& device,
                                                std::initializer_list<VkDescriptorSetLayoutBinding> bindings,
                                                const std::string& name);
// A pool for exactly `maxSets` sets holding the given descriptor counts (sized from what a scene
// holds, never from fixed maxima). Zero-count types are left out.
VkDescriptorPool createDescriptorPool(const Device& device, uint32_t maxSets,
                                      std::vector<VkDescriptorPoolSize> sizes, const std::string& name);
// One set of `layout`, named `name` for graphics debuggers.
VkDescriptorSet allocateDescriptorSet(const Device& device, VkDescriptorPool pool,
                                      VkDescriptorSetLayout layout, const std::string& name);

void writeBufferDescriptor(const Device& device, VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
                           VkBuffer buffer, VkDeviceSize range);
void writeImageDescriptor(const Device& device, VkDescriptorSet set, uint32_t binding, VkSampler sampler,
                          VkImageView view, VkImageLayout layout, uint32_t arrayElement = 0);

}  // namespace common
