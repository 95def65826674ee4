// chapter-18: a mesh's buffers as the shaders read them through pointers: the vertex (as
// common::Vertex) and the two buffer_reference types whose values are the buffers' addresses.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require

//> mesh-pointers
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
//< mesh-pointers
