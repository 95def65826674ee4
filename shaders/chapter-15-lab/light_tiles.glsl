// chapter-15-lab, --light-culling tiled: the light pass's side of the tile lists that the culling
// passes (light_cull_*.comp, chapter-15-lab/light_culling.cpp) build each frame: shadeLights()
// for light_shading.glsl compiled with TILED_LIGHTS. TILE_SET is the descriptor set the form of
// the light pass binds them to (3 for light.frag, 4 for light.comp, whose set 3 is its output).
//
// Lights come in two groups (the C++ orders them so): the first tileView.unboundedLights have no
// range -- directional lights, point lights without one -- and reach every pixel; the rest have a
// range and are shaded only where the pixel's 8x8 tile lists them.
#include "cull_view.glsl"

//> light-tiles
layout(scalar, set = TILE_SET, binding = 0) uniform TileView {
    CullView tileView;
};
layout(std430, set = TILE_SET, binding = 3) readonly buffer TileLists {
    uvec2 tileLists[];  // per tile: first index in tileLightIndices, count (or TILE_OVERFLOW)
};
layout(std430, set = TILE_SET, binding = 4) readonly buffer TileLightIndices {
    uint tileLightIndices[];
};

// `sunLight` is chapter-15's parameter for chapter-16's shadows; the tiled path has none.
vec3 shadeLights(ivec2 pixel, SurfaceSample s, vec3 N, vec3 V, float sunLight) {
    vec3 color = vec3(0.0);
    for (uint i = 0u; i < tileView.unboundedLights; ++i) color += shadeLight(i, s, N, V);
    uvec2 tile = uvec2(pixel) / LIGHT_TILE_SIZE;
    uvec2 list = tileLists[tile.y * tileView.tileCount.x + tile.x];
    if (list.y == TILE_OVERFLOW) {
        // The lists were full: every light with a range, each windowed as without culling.
        for (uint i = tileView.unboundedLights; i < scene.lightCount; ++i) color += shadeLight(i, s, N, V);
    } else {
        for (uint k = 0u; k < list.y; ++k) color += shadeLight(tileLightIndices[list.x + k], s, N, V);
    }
    return color;
}
//< light-tiles
