// chapter-16, beyond the book: what the shadow pass draws each frame, so that a frame pays for what
// changed and not for the whole map (docs/chapter-16.md, "Beyond the book: shadows that cost what
// changed"). After Insomniac's "CSM Scrolling" (Mike Acton and Mike Day, SIGGRAPH 2012):
//   scrolling: a cascade that moved by whole texels (computeCascades snaps it, and keeps its depth
//     window in steps) keeps the texels it still covers; only the bands the move exposed are
//     drawn, scissored. Its layer is addressed toroidally: a texel of the world lives at its
//     world position modulo the map, so nothing is copied -- the light pass adds the cascade's
//     offset (layerOffset) to the place it reads.
//   static and moving casters apart: a draw whose model moved is drawn every frame into a second
//     image (the moving casters'), only in the cascades its bounds touch, and the light pass takes
//     the nearer of the two maps' occluders; the cached map keeps the static casters and never
//     holds a moving one (where a draw starts moving, that place is redrawn without it once). A
//     draw that stops moving for kSettleFrames goes back into it.
//   culling: every draw's bounds in the light's view, against each cascade's box and band, before
//     recording; a draw is submitted only where it can cover a texel being drawn.
// Plain planning on the CPU (shadow_pass.cpp records the plan); tests/unit/shadow_cache_test.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "cascades.hpp"

// --shadow-redraw: how much of the shadow map a frame draws again.
enum class ShadowRedraw {
    Scrolled,          // exposed bands; moving casters apart (the default)
    ScrolledTogether,  // exposed bands; a moving caster's old and new place redrawn in the cached map
    Changed,           // a cascade whole when its matrix changed; every cascade when a caster moved
    Always,            // every cascade whole, every frame
};

// Frames a moving draw must stay still before it goes back into the cached map.
inline constexpr uint32_t kSettleFrames = 8;

// A rectangle of texels, half-open: columns x0..x1-1, rows y0..y1-1. In box space (column 0 at
// the cascade's box's first column) or layer space (where the texels lie in the layer).
struct TexelRect {
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    int64_t area() const { return empty() ? 0 : int64_t(x1 - x0) * int64_t(y1 - y0); }
};
TexelRect intersect(const TexelRect& a, const TexelRect& b);

// The band of a cascade's box (box space) that a move by (dx, dy) texels exposes: none, one or two
// rectangles (an L) covering exactly the texels the old box did not.
std::vector<TexelRect> exposedBands(glm::i64vec2 shift, int32_t mapSize);

// A box-space rectangle placed in a layer whose box starts at `offset` (0..mapSize-1 per axis,
// toroidally): up to four layer-space pieces, each with the viewport origin that puts the box's
// column 0 where the layer holds it.
struct LayerPiece {
    TexelRect scissor;          // layer space
    glm::ivec2 viewport{0, 0};  // the box's origin in the layer: offset, or offset - mapSize
};
std::vector<LayerPiece> placeInLayer(const TexelRect& box, glm::ivec2 offset, int32_t mapSize);

// A draw's bounds in the light's view (x, y, z of lightView; the light looks along -z).
struct CasterBounds {
    glm::vec3 min{0.0f}, max{0.0f};
};
CasterBounds casterBounds(const glm::mat4& lightView, const glm::mat4& model, glm::vec3 meshMin,
                          glm::vec3 meshMax);
// The texels of `cascade`'s box (box space) that a caster with these bounds may cover, one texel
// to spare on every side; empty when it lies outside the box or wholly beyond its depth window.
TexelRect casterTexels(const Cascade& cascade, const CasterBounds& bounds, int32_t mapSize);

// What one draw call records: draw `draw` into the layers of `layers` (bit i: cascade i).
struct ShadowDraw {
    uint32_t draw = 0;
    uint32_t layers = 0;
};
// A batch of draws under one viewport and scissor, into the cached map or the moving casters'.
struct ShadowBatch {
    TexelRect scissor;          // layer space; cleared in each of `layers` first
    glm::ivec2 viewport{0, 0};  // the box's origin in the layer
    uint32_t layers = 0;        // the layers it clears (and the union of its draws' layers)
    std::vector<ShadowDraw> draws;
};

// What a frame records (shadow_pass.cpp): batches into the cached map, then into the moving
// casters' map (clearing first where last frame's moving casters were), and what the light pass reads.
struct ShadowPlan {
    std::vector<ShadowBatch> cached;
    std::vector<ShadowBatch> moving;
    std::vector<std::pair<uint32_t, TexelRect>> movingClears;  // (layer, layer-space rect) to clear
    uint32_t movingLayers = 0;  // bit i: the light pass reads the moving map for cascade i
    glm::ivec2 layerOffset[kMaxCascades]{};
    // Per cascade: texels cleared and drawn, draws and triangles submitted (both maps).
    uint64_t texels[kMaxCascades]{};
    uint32_t draws[kMaxCascades]{};
    uint64_t triangles[kMaxCascades]{};
    uint32_t wholeLayers = 0;  // bit i: cascade i drawn whole this frame
};

// What the scene's draws are, for the plan: each draw's world placement and mesh bounds.
struct CasterInput {
    glm::mat4 model{1.0f};
    glm::vec3 meshMin{0.0f}, meshMax{0.0f};
    uint64_t triangles = 0;
    bool deforms = false;  // its shape changed since the last frame (chapter-17's skinned meshes): it moved
};

// What each layer holds, and each draw as the cached map last saw it.
struct ShadowCache {
    ShadowRedraw form = ShadowRedraw::Scrolled;
    int32_t mapSize = 2048;
    uint32_t count = 0;
    bool valid = false;  // false: every layer drawn whole next frame (first frame, reload, resize)
    struct Held {
        bool valid = false;
        glm::mat4 view{1.0f};
        float texel = 0.0f, depthNear = 0.0f, depthFar = 0.0f;
        glm::i64vec2 origin{0};  // the box's origin when it was last drawn or scrolled
        glm::i64vec2 base{0};    // the box's origin when it was last drawn whole: layer place 0
    } held[kMaxCascades];
    std::vector<glm::mat4> models;                            // each draw's model as last seen
    std::vector<std::pair<glm::vec3, glm::vec3>> meshBounds;  // each draw's mesh bounds as last seen
    std::vector<uint32_t> still;                              // frames each draw has not moved
    std::vector<uint8_t> moving;                              // Scrolled: drawn into the moving casters' map
    std::vector<std::pair<uint32_t, TexelRect>> movingDrawn;  // where the moving map holds casters
    // Totals for the report.
    uint64_t frames = 0;
    uint64_t redraws[kMaxCascades]{};  // frames that drew anything into each cascade
    uint64_t wholeRedraws[kMaxCascades]{};
    uint64_t texels[kMaxCascades]{};
    uint64_t draws[kMaxCascades]{};
    uint64_t triangles[kMaxCascades]{};
    uint64_t culled = 0;  // draws not submitted to a cascade being drawn, for being outside it
    uint64_t movingFrames[kMaxCascades]{};  // frames whose moving casters reached each cascade
};

ShadowCache createShadowCache(ShadowRedraw form, uint32_t mapSize, uint32_t count, size_t draws);
// This frame's plan for `cascades` and the scene's draws (`casters`, in the scene's draw order),
// and the cache updated to hold it. The moving casters' map is the caller's to make, the first
// time a plan has moving batches (shadow_pass.cpp).
ShadowPlan planShadows(ShadowCache& cache, const std::vector<Cascade>& cascades,
                       const std::vector<CasterInput>& casters);
