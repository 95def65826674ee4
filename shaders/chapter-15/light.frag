#version 450
// chapter-15 light pass as the book draws it: a full-screen triangle whose fragment shader shades
// each G-buffer pixel (light_shading.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "light_shading.glsl"

//> light-frag
layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = shadePixel(readGBuffer(inUv), ivec2(gl_FragCoord.xy), 1.0);  // no shadows: the sun reaches every pixel
}
//< light-frag
