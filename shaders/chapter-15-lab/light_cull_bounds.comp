#version 450
// chapter-15-lab, --light-culling tiled, pass 1 of 4: each tile's bounds. One 8x8 group per
// tile reads the G-buffer exactly as the light pass does (readGBuffer, light_shading.glsl) and
// reduces the view-space positions of its surface pixels to a box. A tile with no surface (sky)
// gets none: no light needs it. Compiled with COMPACT_GBUFFER for --gbuffer compact.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "light_shading.glsl"
#include "light_cull.glsl"

//> cull-bounds
layout(local_size_x = LIGHT_TILE_SIZE, local_size_y = LIGHT_TILE_SIZE) in;

// Floats as unsigned integers in the same order, for atomicMin/atomicMax on shared memory.
uint orderable(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderable(uint u) {
    return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7fffffffu : ~u);
}

shared uint boxMin[3];
shared uint boxMax[3];

void main() {
    if (gl_LocalInvocationIndex < 3u) {
        boxMin[gl_LocalInvocationIndex] = 0xffffffffu;
        boxMax[gl_LocalInvocationIndex] = 0u;
    }
    barrier();
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (all(lessThan(pixel, cull.extent))) {
        SurfaceSample s = readGBuffer((vec2(pixel) + 0.5) / vec2(cull.extent));
        vec3 v = mat3(cull.viewRotation) * s.position;
        if (s.surface && !any(isnan(v))) {
            for (int k = 0; k < 3; ++k) {
                atomicMin(boxMin[k], orderable(v[k]));
                atomicMax(boxMax[k], orderable(v[k]));
            }
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uint tile = gl_WorkGroupID.y * cull.tileCount.x + gl_WorkGroupID.x;
        bool surface = boxMin[0] <= boxMax[0];
        tileBounds[2u * tile] = surface ? vec4(fromOrderable(boxMin[0]), fromOrderable(boxMin[1]),
                                               fromOrderable(boxMin[2]), 1.0)
                                        : vec4(0.0);
        tileBounds[2u * tile + 1u] = surface ? vec4(fromOrderable(boxMax[0]), fromOrderable(boxMax[1]),
                                                    fromOrderable(boxMax[2]), 0.0)
                                             : vec4(0.0);
    }
}
//< cull-bounds
