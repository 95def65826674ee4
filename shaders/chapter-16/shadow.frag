#version 450
// chapter-16 shadow pass: the book's variance shadow map -- the depth and its square -- with
// cut-outs' transparent texels casting no shadow.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"

//> shadow-frag
// Opaque materials compile the alpha test away (chapter-15's ALPHA_TEST).
layout(constant_id = 0) const bool ALPHA_TEST = true;

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec2 outMoments;  // R32G32_SFLOAT: depth, depth^2

layout(std430, set = 1, binding = 0) readonly buffer Materials {
    ShaderMaterial materials[];
};
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;

layout(push_constant) uniform Draw {
    layout(offset = DRAW_MATERIAL_OFFSET) uint materialIndex;
} draw;

void main() {
    float depth = gl_FragCoord.z;
    // The book's bias of the second moment by the depth's slope across the texel, against the
    // bleeding a filtered or interpolated map would show. Taken before the discard: derivatives
    // are undefined once a neighbouring fragment may have been discarded.
    float dx = dFdx(depth), dy = dFdy(depth);
    if (ALPHA_TEST) {
        ShaderMaterial material = materials[draw.materialIndex];
        if (material.diffuse.a * texture(albedoTexture, inUv).a < material.alphaCutoff) discard;
    }
    outMoments = vec2(depth, depth * depth + 0.25 * (dx * dx + dy * dy));
}
//< shadow-frag
