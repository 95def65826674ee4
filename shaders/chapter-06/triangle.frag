#version 450
// chapter-06: every fragment of the triangle is red.
#extension GL_GOOGLE_include_directive : require
#include "srgb.glsl"

//> encode
// True when the target image's format does not sRGB-encode what we write (a _UNORM format):
// chapter-06/pipeline.cpp sets it when it makes the pipeline.
layout(constant_id = 0) const bool ENCODE_SRGB = false;

layout(location = 0) out vec4 outColor;

void main() {
    vec3 color = vec3(1.0, 0.0, 0.0);  // linear, like every colour our shaders compute
    outColor = vec4(ENCODE_SRGB ? encodeSrgb(color) : color, 1.0);
}
//< encode
