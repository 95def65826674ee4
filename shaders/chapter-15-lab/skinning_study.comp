#version 450
// chapter-15-lab: the skinning study's compute pass -- chapter-17's skinning pass in the form the
// study asks (skinning_study.glsl): one invocation per vertex, bounds-checked, written once for
// every pass that draws the figure.
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 32) in;

#include "skinning_study.glsl"

// Per vertex: skinned position and normal (6 floats).
layout(set = 0, binding = 3, std430) writeonly buffer Skinned { float skinned[]; };
layout(push_constant) uniform Dispatch { uint count; } dispatch;

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= dispatch.count) return;
    vec3 position, normal;
    skinVertex(index, position, normal);
    normal = normalize(normal);
    for (uint k = 0u; k < 3u; ++k) {
        skinned[index * 6u + k] = position[k];
        skinned[index * 6u + 3u + k] = normal[k];
    }
}
