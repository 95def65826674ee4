// Descriptor helpers.
#include "common/vk/descriptors.hpp"

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

VkDescriptorSetLayoutBinding binding(uint32_t index, VkDescriptorType type, VkShaderStageFlags stages,
                                     uint32_t count) {
    return {.binding = index, .descriptorType = type, .descriptorCount = count, .stageFlags = stages};
}

VkDescriptorSetLayout createDescriptorSetLayout(const Device& device,
                                                std::initializer_list<VkDescriptorSetLayoutBinding> bindings,
                                                const std::string& name) {
    VkDescriptorSetLayoutCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .bindingCount = static_cast<uint32_t>(bindings.size()),
        .pBindings = bindings.begin(),
    };
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(device.handle, &info, nullptr, &layout));
    nameObject(device.handle, layout, name);
    return layout;
}

VkDescriptorPool createDescriptorPool(const Device& device, uint32_t maxSets,
                                      std::vector<VkDescriptorPoolSize> sizes, const std::string& name) {
    std::erase_if(sizes, [](const VkDescriptorPoolSize& size) { return size.descriptorCount == 0; });
    VkDescriptorPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
        .maxSets = maxSets,
        .poolSizeCount = static_cast<uint32_t>(sizes.size()),
        .pPoolSizes = sizes.data(),
    };
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(device.handle, &info, nullptr, &pool));
    nameObject(device.handle, pool, name);
    return pool;
}

VkDescriptorSet allocateDescriptorSet(const Device& device, VkDescriptorPool pool,
                                      VkDescriptorSetLayout layout, const std::string& name) {
    VkDescriptorSetAllocateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
        .descriptorPool = pool,
        .descriptorSetCount = 1,
        .pSetLayouts = &layout,
    };
    VkDescriptorSet set = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateDescriptorSets(device.handle, &info, &set));
    nameObject(device.handle, set, name);
    return set;
}

void writeBufferDescriptor(const Device& device, VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
                           VkBuffer buffer, VkDeviceSize range) {
    VkDescriptorBufferInfo bufferInfo{.buffer = buffer, .offset = 0, .range = range};
    VkWriteDescriptorSet write{
        .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
        .dstSet = set,
        .dstBinding = binding,
        .descriptorCount = 1,
        .descriptorType = type,
        .pBufferInfo = &bufferInfo,
    };
    vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

void writeImageDescriptor(const Device& device, VkDescriptorSet set, uint32_t binding, VkSampler sampler,
                          VkImageView view, VkImageLayout layout, uint32_t arrayElement) {
    VkDescriptorImageInfo imageInfo{.sampler = sampler, .imageView = view, .imageLayout = layout};
    VkWriteDescriptorSet write{
        .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
        .dstSet = set,
        .dstBinding = binding,
        .dstArrayElement = arrayElement,
        .descriptorCount = 1,
        .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
        .pImageInfo = &imageInfo,
    };
    vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

}  // namespace common
