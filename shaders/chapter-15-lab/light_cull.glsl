// chapter-15-lab, --light-culling tiled: the culling passes' descriptor set (set 3), shared by
// light_cull_bounds.comp, light_cull.comp and light_cull_scan.comp. chapter-15-lab/
// light_culling.cpp creates and fills it; the light pass reads bindings 0, 3 and 4 (light_tiles.glsl).
#include "gpu_types.glsl"
#include "cull_view.glsl"

//> cull-set
layout(scalar, set = 3, binding = 0) uniform Cull {
    CullView cull;  // this frame's camera and tile grid
};
layout(std430, set = 3, binding = 1) buffer TileBounds {
    vec4 tileBounds[];  // per tile: view-space min (w: 1 if the tile has a surface), max
};
layout(std430, set = 3, binding = 2) buffer TileCounts {
    uint tileCounts[];  // per tile: lights that reach it (the count pass)
};
layout(std430, set = 3, binding = 3) buffer TileLists {
    uvec2 tileLists[];  // per tile: first index in tileLightIndices, count (or TILE_OVERFLOW)
};
layout(std430, set = 3, binding = 4) buffer TileLightIndices {
    uint tileLightIndices[];  // cull.capacity entries, the tiles' lists one after another
};
layout(std430, set = 3, binding = 5) buffer CullStats {
    uint pairs;          // light-tile pairs found
    uint maxTileLights;  // the longest list
    uint overflowTiles;  // tiles whose list did not fit (shaded with every light)
    uint litTiles;       // tiles that some light with a range reaches
};
layout(std430, set = 3, binding = 6) buffer LargeLights {
    uvec3 largeDispatch;  // a VkDispatchIndirectCommand: one group per large light
    uint largeLights[];   // lights whose rectangle has more than LARGE_LIGHT_TILES tiles
};
//< cull-set
