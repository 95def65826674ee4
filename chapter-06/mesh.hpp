// chapter-06: meshes -- the book's VertexBufferStructure (how the pipeline reads a vertex),
// MeshData (a mesh on the CPU) and VulkanMesh with loadMeshes (the same mesh in device-local
// buffers, copied there through host-visible staging buffers). Deliberate repetition: later
// chapters upload through common/vk/buffer.cpp (beginStaging, uploadStaged, endStaging), the same
// calls wrapped.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "buffer.hpp"
#include "common/vk/device.hpp"

//> vertex-input
// The book's VertexBufferStructure: one binding of tightly packed vertices, one attribute
// (location 0, three 32-bit floats) for the position. The pipeline keeps a pointer to `state`,
// which points at the other two members: the struct must stay where it is until then.
struct VertexInput {
    VkVertexInputBindingDescription binding;
    VkVertexInputAttributeDescription position;
    VkPipelineVertexInputStateCreateInfo state;
};

void describeVertexInput(VertexInput& input);
//< vertex-input

//> mesh-data
// The book's MeshData: what the application knows about a mesh before the GPU has it.
struct MeshData {
    std::vector<float> positions;  // x, y, z per vertex
    std::vector<uint32_t> indices;
};

// The book's VulkanMesh: the same data in device-local buffers.
struct Mesh {
    Buffer vertices;
    Buffer indices;
    uint32_t indexCount = 0;
};
//< mesh-data

// Uploads every mesh; one submission and one wait for all of them.
std::vector<Mesh> loadMeshes(const common::Device& device, const std::vector<MeshData>& meshData);
void destroyMeshes(const common::Device& device, std::vector<Mesh>& meshes);
