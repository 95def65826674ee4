#version 450
// chapter-18 scene pass: chapter-15's scene.vert with the vertex read through pointers instead of
// the vertex input (pulled_mesh.glsl).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "pulled_mesh.glsl"

//> scene-vert
layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec3 outBitangent;
layout(location = 4) out vec2 outUv;

layout(set = 0, binding = 0) uniform CameraBlock {
    CameraUniform camera;  // gpu_types.glsl
};

void main() {
    Vertex v = pulledVertex();
    vec4 worldPosition = draw.model * vec4(v.position, 1.0);
    gl_Position = camera.projection * camera.view * worldPosition;
    outWorldPosition = worldPosition.xyz;
    outNormal = draw.normalMatrix * v.normal;
    outTangent = draw.normalMatrix * v.tangent;
    outBitangent = draw.normalMatrix * v.bitangent;
    outUv = v.uv;
}
//< scene-vert
