#version 450
// chapter-15 scene pass: positions, and the tangent frame in world space for normal mapping.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"

//> scene-vert
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBitangent;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec3 outBitangent;
layout(location = 4) out vec2 outUv;

layout(set = 0, binding = 0) uniform CameraBlock {
    CameraUniform camera;  // gpu_types.glsl
};

layout(push_constant) uniform DrawBlock {
    DrawConstants draw;  // gpu_types.glsl; the normal matrix is made on the CPU
};

void main() {
    vec4 worldPosition = draw.model * vec4(inPosition, 1.0);
    gl_Position = camera.projection * camera.view * worldPosition;
    outWorldPosition = worldPosition.xyz;
    // Directions are transformed by the inverse-transpose, which keeps the normal perpendicular
    // to the surface under non-uniform scale. (The tangent and bitangent lie in the surface and
    // could use the model matrix itself; after the Gram-Schmidt step in the fragment shader
    // either choice gives the same frame.)
    outNormal = draw.normalMatrix * inNormal;
    outTangent = draw.normalMatrix * inTangent;
    outBitangent = draw.normalMatrix * inBitangent;
    outUv = inUv;
}
//< scene-vert
