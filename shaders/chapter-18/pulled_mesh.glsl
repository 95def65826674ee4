// chapter-18: the draw's mesh, read through the pointers it pushes (chapter-18/mesh_pulling.hpp):
// index gl_VertexIndex of the index buffer, then that vertex of the vertex buffer.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require

//> pulled-mesh
// common::Vertex, 56 bytes, as chapter-15's vertex input reads it.
struct Vertex {
    vec3 position;
    vec3 normal;
    vec3 tangent;
    vec3 bitangent;
    vec2 uv;
};
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer IndexBuffer {
    uint indices[];
};
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer VertexBuffer {
    Vertex vertices[];
};

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
