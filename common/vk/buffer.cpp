// Buffer creation and staged uploads.
#include "common/vk/buffer.hpp"

#include <cstring>

#include "common/core/check.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name) {
    Buffer buffer;
    buffer.size = size;
    VkBufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VK_CHECK(vkCreateBuffer(device.handle, &info, nullptr, &buffer.handle));
    nameObject(device.handle, buffer.handle, name);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle, buffer.handle, &requirements);
    const bool addressed = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
    buffer.memory = allocateMemory(device, requirements, memoryFlags, name,
                                   addressed ? VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT : 0);
    VK_CHECK(vkBindBufferMemory(device.handle, buffer.handle, buffer.memory, 0));
    if (addressed) {  // chapter-18 writes this call out (chapter-18/mesh_pulling.cpp)
        VkBufferDeviceAddressInfo addressInfo{.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO,
                                              .buffer = buffer.handle};
        buffer.address = vkGetBufferDeviceAddress(device.handle, &addressInfo);
    }
    if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VK_CHECK(vkMapMemory(device.handle, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
    return buffer;
}

void destroyBuffer(const Device& device, Buffer& buffer) {
    vkDestroyBuffer(device.handle, buffer.handle, nullptr);
    vkFreeMemory(device.handle, buffer.memory, nullptr);  // also unmaps
    buffer = {};
}

StagingBatch beginStaging(const Device& device) {
    return StagingBatch{beginOneTimeCommands(device), {}};
}

Buffer uploadStaged(const Device& device, StagingBatch& batch, const void* data, VkDeviceSize size,
                    VkBufferUsageFlags usage, const std::string& name) {
    // HOST_COHERENT: the memcpy is visible to the device without vkFlushMappedMemoryRanges, and
    // vkQueueSubmit makes host writes made before it available to the copy.
    Buffer staging = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  "staging: " + name);
    std::memcpy(staging.mapped, data, size);
    batch.stagingBuffers.push_back(staging);

    Buffer target = createBuffer(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = size};
    vkCmdCopyBuffer(batch.commandBuffer, staging.handle, target.handle, 1, &region);
    return target;
}

//> staging
void endStaging(const Device& device, StagingBatch& batch) {
    // Waiting on the fence only tells the host the copies are done; this barrier is what makes
    // the copied bytes visible to every later read on the device (vertex fetch, index fetch,
    // shaders) in later submissions. The readers are named stage by stage: vertex input for
    // vertex and index buffers, the shader stages for uniform and storage buffers.
    VkMemoryBarrier barrier{
        .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
        .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
        .dstAccessMask = VK_ACCESS_MEMORY_READ_BIT,
    };
    VkPipelineStageFlags readers = VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    vkCmdPipelineBarrier(batch.commandBuffer, VK_PIPELINE_STAGE_TRANSFER_BIT, readers, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    submitOneTimeCommands(device, batch.commandBuffer);
    for (Buffer& staging : batch.stagingBuffers) destroyBuffer(device, staging);
    batch = {};
}
//< staging

}  // namespace common
