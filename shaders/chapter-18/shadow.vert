#version 450
// chapter-18 shadow pass: chapter-16's shadow.vert with the vertex read through pointers
// (pulled_mesh.glsl); the geometry shader then sends each triangle to its cascades as before.
#extension GL_GOOGLE_include_directive : require
#include "pulled_mesh.glsl"

//> shadow-vert
layout(location = 0) out vec2 outUv;
layout(location = 1) flat out uint outLayers;

void main() {
    Vertex v = pulledVertex();
    gl_Position = draw.model * vec4(v.position, 1.0);
    outUv = v.uv;
    outLayers = uint(gl_InstanceIndex);  // the cascades the draw goes to (its firstInstance)
}
//< shadow-vert
