// pointer_test SHADER.spv: chapter-18's vertex pulling reads what C++ pushed and stored, from
// buffers that share one memory allocation. C++ fills PulledDrawConstants (chapter-18/
// mesh_pulling.hpp) and an index and a vertex buffer bound at offsets of ONE VkDeviceMemory
// allocated with VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT -- no dedicated allocation, which the book's
// text says pointer-read buffers need -- and a compute shader that includes
// shaders/chapter-18/pulled_mesh.glsl reads the block and pulls one vertex per index; every field
// must come back as written. Exit 0 when all agree.
#include <cstdio>
#include <cstring>
#include <vector>

#include "../tools/gpu_compute.hpp"
#include "chapter-18/mesh_pulling.hpp"
#include "common/app/cli.hpp"
#include "common/core/check.hpp"
#include "common/model/model.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/memory.hpp"

namespace {

const char* gShaderPath = nullptr;

void run(const common::Options& options) {
    constexpr uint32_t kVertices = 5, kIndices = 7;
    const uint32_t indices[kIndices] = {4, 0, 3, 3, 1, 2, 4};  // a vertex twice, out of order
    std::vector<common::Vertex> vertices(kVertices);
    float next = 1000.0f;
    for (common::Vertex& v : vertices) {
        v.position = {next, next + 1, next + 2};
        v.normal = {next + 3, next + 4, next + 5};
        v.tangent = {next + 6, next + 7, next + 8};
        v.bitangent = {next + 9, next + 10, next + 11};
        v.uv = {next + 12, next + 13};
        next += 14;
    }
    PulledDrawConstants draw{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) draw.model[c][r] = float(4 * c + r + 1);
    for (int k = 0; k < 9; ++k) draw.normalMatrix[k] = float(100 + k);

    common::Instance instance = common::createInstance("pointer_test", options.validation, {});
    common::Device device = common::createDevice(instance, VK_NULL_HANDLE, options.device,
                                                 {.scalarBlockLayout = true, .bufferDeviceAddress = true});
    // Two buffers, one allocation: the index buffer at offset 0, the vertex buffer after it.
    VkBuffer buffers[2]{};
    VkDeviceSize sizes[2] = {sizeof(indices), vertices.size() * sizeof(common::Vertex)};
    VkMemoryRequirements requirements[2];
    for (int b = 0; b < 2; ++b) {
        VkBufferCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
            .size = sizes[b],
            .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
            .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
        VK_CHECK(vkCreateBuffer(device.handle, &info, nullptr, &buffers[b]));
        vkGetBufferMemoryRequirements(device.handle, buffers[b], &requirements[b]);
    }
    const VkDeviceSize alignment = requirements[1].alignment;
    const VkDeviceSize vertexOffset = (requirements[0].size + alignment - 1) / alignment * alignment;
    VkMemoryRequirements shared = requirements[0];
    shared.size = vertexOffset + requirements[1].size;
    shared.memoryTypeBits &= requirements[1].memoryTypeBits;
    VkDeviceMemory memory = common::allocateMemory(
        device, shared, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
        "indices and vertices", VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT);
    VK_CHECK(vkBindBufferMemory(device.handle, buffers[0], memory, 0));
    VK_CHECK(vkBindBufferMemory(device.handle, buffers[1], memory, vertexOffset));
    void* mapped = nullptr;
    VK_CHECK(vkMapMemory(device.handle, memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    std::memcpy(mapped, indices, sizeof(indices));
    std::memcpy(static_cast<char*>(mapped) + vertexOffset, vertices.data(), sizes[1]);
    VkDeviceAddress addresses[2];
    for (int b = 0; b < 2; ++b) {
        VkBufferDeviceAddressInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO,
                                       .buffer = buffers[b]};
        addresses[b] = vkGetBufferDeviceAddress(device.handle, &info);
    }
    draw.indices = addresses[0];
    draw.vertices = addresses[1];

    std::vector<float> expected;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) expected.push_back(draw.model[c][r]);
    expected.insert(expected.end(), draw.normalMatrix, draw.normalMatrix + 9);
    for (uint32_t index : indices) {
        const common::Vertex& v = vertices[index];
        const float* fields = &v.position.x;  // 14 packed floats (common::Vertex)
        expected.insert(expected.end(), fields, fields + 14);
    }
    common::Buffer results = common::createBuffer(
        device, expected.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "results");
    std::memset(results.mapped, 0xff, expected.size() * sizeof(float));  // NaN until written
    runCompute(device, gShaderPath, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, results.handle}}, &draw,
               kPulledVertexConstants, kIndices);

    const float* fields = static_cast<const float*>(results.mapped);
    size_t wrong = 0;
    for (size_t i = 0; i < expected.size(); ++i)
        if (fields[i] != expected[i]) {
            std::printf("field %zu: the shader read %g, C++ wrote %g\n", i, fields[i], expected[i]);
            ++wrong;
        }
    std::printf(
        "%zu fields of PulledDrawConstants and %u pulled vertices, read through pointers into one "
        "allocation (vertices at offset %llu), %zu disagree\n",
        expected.size(), kIndices, static_cast<unsigned long long>(vertexOffset), wrong);
    common::destroyBuffer(device, results);
    for (VkBuffer buffer : buffers) vkDestroyBuffer(device.handle, buffer, nullptr);
    vkFreeMemory(device.handle, memory, nullptr);
    common::destroyDevice(device);
    common::destroyInstance(instance);
    if (wrong != 0) throw common::Failure("chapter-18's C++ and GLSL disagree on what a draw pulls");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: pointer_test SHADER.spv [--device NAME] [--validation]\n");
        return 2;
    }
    gShaderPath = argv[1];
    argv[1] = argv[0];  // the rest is the usual command line
    return common::runChapter(argc - 1, argv + 1,
                              {"pointer_test", "chapter-18's vertex pulling read back", {}}, run);
}
