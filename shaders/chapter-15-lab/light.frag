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
    float visibility = 1.0;
    SurfaceSample s = readGBuffer(inUv);
#ifdef SUN_SHADOWS
    // --shadows: the sun's visibility at the pixel first (chapter-16's light pass); view 6, the
    // visibility alone.
    vec3 world = s.position + scene.cameraPosition;
    int cascade = cascadeOf(-(cascades.cameraView * vec4(world, 1.0)).z);
    visibility = s.surface && cascades.count > 0 ? labSunVisibility(world, surfaceNormal(s.normal), cascade) : 1.0;
    if (show.view == 6) {
        outColor = vec4(vec3(visibility), 1.0);
        return;
    }
#endif
    outColor = shadePixel(s, ivec2(gl_FragCoord.xy), visibility);
}
//< light-frag
