#version 450
// chapter-15-lab: the skinning study's vertex shader. Either it reads the vertex the compute pass
// skinned (kSkinHere false: what chapter-17's passes draw), or it skins the vertex itself
// (skinning_study.glsl), in every pass that draws the figure. Compiled with STORE, it skins and
// writes what it skinned, for the study's check against the double-precision reference.
#extension GL_GOOGLE_include_directive : require

#include "skinning_study.glsl"

layout(constant_id = 3) const bool kSkinHere = false;

#ifdef STORE
layout(set = 0, binding = 3, std430) writeonly buffer Skinned { float skinned[]; };
#else
layout(set = 0, binding = 3, std430) readonly buffer Skinned { float skinned[]; };
#endif
layout(push_constant) uniform Pass { mat4 viewProjection; } pass;

layout(location = 0) out vec3 outNormal;

void main() {
    uint index = uint(gl_VertexIndex);
    vec3 position, normal;
#ifdef STORE
    skinVertex(index, position, normal);
    normal = normalize(normal);
    for (uint k = 0u; k < 3u; ++k) {
        skinned[index * 6u + k] = position[k];
        skinned[index * 6u + 3u + k] = normal[k];
    }
#else
    if (kSkinHere) {
        skinVertex(index, position, normal);
        normal = normalize(normal);
    } else {
        position = vec3(skinned[index * 6u], skinned[index * 6u + 1u], skinned[index * 6u + 2u]);
        normal = vec3(skinned[index * 6u + 3u], skinned[index * 6u + 4u], skinned[index * 6u + 5u]);
    }
#endif
    outNormal = normal;
    gl_Position = pass.viewProjection * vec4(position, 1.0);
}
