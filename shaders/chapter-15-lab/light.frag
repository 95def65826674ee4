#version 450
// chapter-15-lab light pass as chapter-15 draws it, a full-screen triangle, with the lab's
// G-buffer layouts and tiled culling (light_shading.glsl). light.comp does the same in a compute
// dispatch.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#define TILE_SET 3  // --light-culling tiled: the tile lists (light_tiles.glsl)
#include "light_shading.glsl"

//> light-frag
layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = shadePixel(inUv, ivec2(gl_FragCoord.xy));
}
//< light-frag
