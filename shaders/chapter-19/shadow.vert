#version 450
// chapter-19 shadow pass: chapter-18's shadow.vert through the draw's instance (instances.glsl),
// which also carries the cascades the geometry shader sends it to.
#extension GL_GOOGLE_include_directive : require
#include "instances.glsl"

//> shadow-vert
layout(location = 0) out vec2 outUv;
layout(location = 1) flat out uint outLayers;

void main() {
    Instance instance = thisInstance();
    Vertex v = pulledVertex(instance);
    gl_Position = draw.matrices.matrices[instance.matrix].model * vec4(v.position, 1.0);
    outUv = v.uv;
    outLayers = instance.layers;
}
//< shadow-vert
