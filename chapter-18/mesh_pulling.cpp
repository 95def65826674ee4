// chapter-18: vertex pulling (mesh_pulling.hpp).
#include "mesh_pulling.hpp"

//> pulled-draw
void recordPulledMesh(VkCommandBuffer cmd, VkPipelineLayout layout, const MeshDrawing& drawing,
                      const common::GpuScene& scene, const common::Draw& draw, uint32_t firstInstance) {
    const common::GpuMesh& mesh = scene.meshes[draw.mesh];
    // The buffers' addresses (vkGetBufferDeviceAddress when they were made: common/vk/buffer.cpp);
    // nothing is bound. The loader checked every index against the mesh's vertex count: a pointer
    // has no robust-access net, and an index past the buffer would read whatever memory follows.
    PulledDrawConstants constants{.model = draw.model,
                                  .indices = mesh.indices.address,
                                  .vertices = mesh.vertices.address,
                                  .normalMatrix = {}};
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
            constants.normalMatrix[3 * column + row] = draw.normalMatrix[column][row];
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, drawing.vertexConstants, &constants);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, drawing.materialOffset, sizeof(uint32_t),
                       &draw.material);
    // One vertex shader invocation per index: gl_VertexIndex runs over 0 .. indexCount - 1.
    vkCmdDraw(cmd, mesh.indexCount, 1, 0, firstInstance);
}
//< pulled-draw
