#version 450
// chapter-15-lab shadow study: the shadow map for depth comparison (PCF) -- the depth alone, with
// cut-outs' transparent texels discarded (chapter-16's shadow.frag writes the moments instead).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"

layout(constant_id = 0) const bool ALPHA_TEST = true;

layout(location = 0) in vec2 inUv;

layout(std430, set = 1, binding = 0) readonly buffer Materials {
    ShaderMaterial materials[];
};
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;

layout(push_constant) uniform Draw {
    layout(offset = DRAW_MATERIAL_OFFSET) uint materialIndex;
} draw;

void main() {
    if (ALPHA_TEST) {
        ShaderMaterial material = materials[draw.materialIndex];
        if (material.diffuse.a * texture(albedoTexture, inUv).a < material.alphaCutoff) discard;
    }
}
