// chapter-15-lab, --light-culling tiled (chapter-15-lab/light_culling.cpp): the culling passes'
// view of the frame, one uniform buffer per frame in flight, scalar layout, 104 bytes. Its C++
// twin is CullView in chapter-15-lab/light_culling.hpp; the layout test checks both agree.
#ifndef CULL_VIEW_GLSL
#define CULL_VIEW_GLSL

//> cull-view
// Pixels per tile side. 8 rather than the usual 16: a tile's list holds the lights of all its
// pixels, and when lights are small on screen (65,536 of them) 16x16 tiles list several times
// more lights than reach any one pixel (docs/performance.md, "Many lights").
const uint LIGHT_TILE_SIZE = 8u;
const uint TILE_OVERFLOW = 0xffffffffu;  // a tile whose list did not fit: it loops over every light
struct CullView {
    mat4 viewRotation;       // camera-relative world space to view space (looking along -z)
    vec2 projectionScale;    // the projection's [0][0] and [1][1]: view-space slope to NDC
    float near;              // the near plane: nothing closer is drawn
    float margin;            // how far a stored surface position may lie from its pixel's ray
    uvec2 tileCount;         // tiles across and down
    uvec2 extent;            // the G-buffer's size in pixels
    uint capacity;           // light indices the tile lists can hold, all tiles together
    uint unboundedLights;    // the first lights (no range): shaded at every pixel, never listed
};
//< cull-view

#endif
