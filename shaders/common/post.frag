#version 450
// The post pass (common/passes/post_pass.cpp, chapters 14 and 15): the light output into the presentation image -- optionally
// anti-aliased with FXAA, clamped to the displayable range, sRGB-encoded when the target format
// does not do it in hardware. Both choices are specialization constants: fixed when the pipeline
// is created, so the shader compiler removes the branches.
#extension GL_GOOGLE_include_directive : require
#include "fxaa.glsl"
#include "srgb.glsl"

//> post-frag
layout(constant_id = 0) const bool USE_FXAA = false;
layout(constant_id = 1) const bool ENCODE_SRGB = false;  // true for a _UNORM target format (common::encodesSrgb)

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

layout(set = 0, binding = 0) uniform sampler2D lightOutput;

void main() {
    vec3 color = USE_FXAA ? fxaa(lightOutput, inUv) : texture(lightOutput, inUv).rgb;
    color = clamp(color, 0.0, 1.0);
    outColor = vec4(ENCODE_SRGB ? encodeSrgb(color) : color, 1.0);
}
//< post-frag
