// chapter-06: meshes and the staging copy.
#include "mesh.hpp"

#include <cstring>

#include "common/core/check.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"

//> describe-vertex-input
void describeVertexInput(VertexInput& input) {
    input.binding = {
        .binding = 0,
        .stride = 3 * sizeof(float),
        .inputRate = VK_VERTEX_INPUT_RATE_VERTEX,  // one element per vertex, not per instance
    };
    input.position = {
        .location = 0,  // layout(location = 0) in vec3 position; in triangle.vert
        .binding = 0,
        .format = VK_FORMAT_R32G32B32_SFLOAT,
        .offset = 0,
    };
    input.state = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = 1,
        .pVertexBindingDescriptions = &input.binding,
        .vertexAttributeDescriptionCount = 1,
        .pVertexAttributeDescriptions = &input.position,
    };
}
//< describe-vertex-input

namespace {

//> stage
// One buffer's trip to the GPU: the bytes go into a new host-visible staging buffer (HOST_COHERENT:
// no flush needed; vkQueueSubmit makes host writes made before it visible to the device), and a
// copy into a new device-local buffer is recorded. The staging buffer must live until the copy
// has run, so it is handed back to be freed after the wait.
Buffer stage(const common::Device& device, VkCommandBuffer cmd, const void* data, VkDeviceSize size,
             VkBufferUsageFlags usage, const std::string& name, std::vector<Buffer>& stagingBuffers) {
    Buffer staging = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  std::string("staging: ").append(name));
    std::memcpy(staging.mapped, data, size);
    stagingBuffers.push_back(staging);

    Buffer target = createBuffer(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = size};
    vkCmdCopyBuffer(cmd, staging.handle, target.handle, 1, &region);
    return target;
}
//< stage

}  // namespace

//> load-meshes
// Device-local memory is the fastest for the GPU to read, but the CPU usually cannot write it.
// So every buffer goes through a staging buffer, and all the copies are recorded into one
// command buffer, submitted once and waited for once.
std::vector<Mesh> loadMeshes(const common::Device& device, const std::vector<MeshData>& meshData) {
    VkCommandBufferAllocateInfo allocInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = device.oneTimePool,  // a pool for short-lived command buffers (common/vk/device.cpp)
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &cmd));
    common::nameObject(device.handle, cmd, "mesh upload");
    VkCommandBufferBeginInfo beginInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));

    std::vector<Buffer> stagingBuffers;
    std::vector<Mesh> meshes;
    for (const MeshData& data : meshData) {
        Mesh mesh;
        std::string name = std::string("mesh ").append(std::to_string(meshes.size()));
        mesh.vertices = stage(device, cmd, data.positions.data(), data.positions.size() * sizeof(float),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, name + " vertices", stagingBuffers);
        mesh.indices = stage(device, cmd, data.indices.data(), data.indices.size() * sizeof(uint32_t),
                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT, name + " indices", stagingBuffers);
        mesh.indexCount = static_cast<uint32_t>(data.indices.size());
        meshes.push_back(mesh);
    }

    // The fence below only tells the CPU that the copies are done. This barrier is what makes
    // the copied bytes visible to the GPU's later reads of them, in later submissions: vertex
    // and index fetch (VERTEX_INPUT).
    VkMemoryBarrier barrier{
        .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
        .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
        .dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT,
    };
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
    VK_CHECK(vkEndCommandBuffer(cmd));

    // Submit, and wait on a fence until the GPU has run the copies; then the staging buffers go.
    VkFence done = common::createFence(device, false);
    common::nameObject(device.handle, done, "mesh upload done");
    VkSubmitInfo submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .commandBufferCount = 1,
        .pCommandBuffers = &cmd,
    };
    VK_CHECK(vkQueueSubmit(device.queue, 1, &submit, done));
    VK_CHECK(vkWaitForFences(device.handle, 1, &done, VK_TRUE, UINT64_MAX));
    vkDestroyFence(device.handle, done, nullptr);
    vkFreeCommandBuffers(device.handle, device.oneTimePool, 1, &cmd);
    for (Buffer& staging : stagingBuffers) destroyBuffer(device, staging);
    return meshes;
}
//< load-meshes

void destroyMeshes(const common::Device& device, std::vector<Mesh>& meshes) {
    for (Mesh& mesh : meshes) {
        destroyBuffer(device, mesh.indices);
        destroyBuffer(device, mesh.vertices);
    }
    meshes.clear();
}
