// chapter-19: what a draw of an indirect command finds by its gl_InstanceIndex -- its instance in
// the frame's instance buffer (chapter-19/global_buffers.hpp's InstanceData: its matrices' index,
// the cascades it goes to, its mesh's vertex buffer) and its matrices -- through the two addresses
// the pass pushes once. The index comes from the bound index buffer: gl_VertexIndex is its value.
#extension GL_GOOGLE_include_directive : require
#include "../chapter-18/mesh_pointers.glsl"  // Vertex, VertexBuffer
#include "gpu_types.glsl"                    // DrawConstants: the model and normal matrices

//> instances
// InstanceData, 16 bytes (scalar).
struct Instance {
    uint matrix;  // its draw's DrawConstants in the matrices buffer
    uint layers;  // the shadow pass: the cascades it goes to (bit i); 0 in the scene pass
    VertexBuffer vertexBuffer;
};
layout(buffer_reference, scalar, buffer_reference_align = 8) readonly buffer Instances {
    Instance instances[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Matrices {
    DrawConstants matrices[];  // 112 bytes each, as chapter-15 pushed them
};

// Pushed once per pass (16 bytes); the fragment stage's material index follows at 16.
layout(push_constant, scalar) uniform DrawBlock {
    Instances instances;
    Matrices matrices;
} draw;

// gl_InstanceIndex is the command's firstInstance plus the instance's number within it.
Instance thisInstance() {
    return draw.instances.instances[gl_InstanceIndex];
}
// An indexed draw: gl_VertexIndex is the index's value (the commands' vertexOffset is 0).
Vertex pulledVertex(Instance instance) {
    return instance.vertexBuffer.vertices[gl_VertexIndex];
}
//< instances
