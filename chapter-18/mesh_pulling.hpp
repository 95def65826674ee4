// chapter-18: vertex pulling -- the book's chapter-18 change to ScnRender and ShadowRender. The
// scene and shadow pipelines have no vertex input state; a draw pushes the addresses of its mesh's
// index and vertex buffers, and the vertex shader reads index gl_VertexIndex, then that vertex
// (shaders/chapter-18/pulled_mesh.glsl), for vkCmdDraw over the index count.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "chapter-15/scene_pass.hpp"
#include "common/scene/gpu_scene.hpp"

// The vertex stage's push constants (scalar layout, pulled_mesh.glsl's DrawBlock): the model
// matrix, the two addresses, the normal matrix's three columns packed (the book pushes the model
// matrix and the addresses, 80 bytes, and inverts the matrix per vertex; ours is made once per
// draw on the CPU, as chapter-15's). 116 bytes: the material index follows at 116, and the whole
// fits the 128 bytes every device has.
struct PulledDrawConstants {
    glm::mat4 model;
    VkDeviceAddress indices;   // uint32_t per index
    VkDeviceAddress vertices;  // common::Vertex, 56 bytes
    float normalMatrix[9];     // column-major 3x3, packed
};
inline constexpr uint32_t kPulledVertexConstants =
    offsetof(PulledDrawConstants, normalMatrix) + 9 * sizeof(float);
static_assert(offsetof(PulledDrawConstants, indices) == 64 && kPulledVertexConstants == 116);
// The fragment stage's material index: chapter-15's and chapter-16's fragment shaders are compiled
// for chapter-18 with DRAW_MATERIAL_OFFSET=116 (CMakeLists.txt).
inline constexpr uint32_t kPulledMaterialOffset = kPulledVertexConstants;

// One draw: its mesh's addresses and matrices pushed, vkCmdDraw over its index count.
void recordPulledMesh(VkCommandBuffer cmd, VkPipelineLayout layout, const MeshDrawing& drawing,
                      const common::GpuScene& scene, const common::Draw& draw, uint32_t firstInstance);

// The scene and shadow passes' MeshDrawing for vertex pulling.
inline constexpr MeshDrawing kPulledMeshes{.vertexInput = false,
                                           .vertexConstants = kPulledVertexConstants,
                                           .materialOffset = kPulledMaterialOffset,
                                           .record = recordPulledMesh};
