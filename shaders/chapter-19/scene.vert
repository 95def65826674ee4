#version 450
// chapter-19 scene pass: chapter-18's scene.vert, its matrices and mesh found through its instance
// (instances.glsl) instead of push constants of its own.
#extension GL_GOOGLE_include_directive : require
#include "instances.glsl"

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
    Instance instance = thisInstance();
    DrawConstants matrices = draw.matrices.matrices[instance.matrix];
    Vertex v = pulledVertex(instance);
    vec4 worldPosition = matrices.model * vec4(v.position, 1.0);
    gl_Position = camera.projection * camera.view * worldPosition;
    outWorldPosition = worldPosition.xyz;
    outNormal = matrices.normalMatrix * v.normal;
    outTangent = matrices.normalMatrix * v.tangent;
    outBitangent = matrices.normalMatrix * v.bitangent;
    outUv = v.uv;
}
//< scene-vert
