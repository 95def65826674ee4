#version 450
// chapter-15-lab light pass as a compute dispatch (--light-pass compute): one invocation per pixel,
// shading it exactly as light.frag does (light_shading.glsl) and storing the colour into the light
// output as a storage image. No rasteriser, no full-screen triangle: on GPUs where few units
// rasterise (NVIDIA H100/H200), all of the chip's compute units take part.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#define TILE_SET 4  // --light-culling tiled: the tile lists (light_tiles.glsl); set 3 is the output
#include "light_shading.glsl"

//> light-comp
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 3, binding = 0, rgba32f) uniform writeonly image2D lightOutput;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(lightOutput);
    if (pixel.x >= size.x || pixel.y >= size.y) return;  // the last row and column of groups overhang
    imageStore(lightOutput, pixel, shadePixel(readGBuffer((vec2(pixel) + 0.5) / vec2(size)), pixel, 1.0));
}
//< light-comp
