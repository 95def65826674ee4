// chapter-18: the draw's mesh, read through the pointers it pushes (chapter-18/mesh_pulling.hpp):
// index gl_VertexIndex of the index buffer, then that vertex of the vertex buffer.
#extension GL_GOOGLE_include_directive : require
#include "mesh_pointers.glsl"  // Vertex, IndexBuffer, VertexBuffer

//> pulled-mesh
// PulledDrawConstants: 116 bytes; the fragment stage's material index follows at 116.
layout(push_constant, scalar) uniform DrawBlock {
    mat4 model;
    IndexBuffer indexBuffer;
    VertexBuffer vertexBuffer;
    mat3 normalMatrix;  // packed columns: the inverse-transpose of the model matrix
} draw;

// The index of the vertex this invocation shades: gl_VertexIndex runs over 0 .. the draw's count - 1
// (tests/chapters/pointer_test.cpp reads through the same block from a compute shader).
#ifndef PULLED_INDEX
#define PULLED_INDEX gl_VertexIndex
#endif
Vertex pulledVertex() {
    return draw.vertexBuffer.vertices[draw.indexBuffer.indices[PULLED_INDEX]];
}
//< pulled-mesh
