// chapter-16: the cascades of a directional light's shadow -- where the camera's view is split,
// and the light's orthographic camera for each slice -- computed on the CPU every frame. The
// book's CascadeShadows and ShadowUtils.updateCascadeShadows, right where the book's is fragile:
// the light's up vector never nearly parallel to its direction, and texel snapping that snaps.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/frame_cost.hpp"

// The camera whose view the cascades cover.
struct CascadeCamera {
    glm::mat4 view{1.0f};  // world -> view (right-handed, looking down -z)
    float fovY = 1.0f;     // vertical field of view, radians
    float aspect = 1.0f;   // width / height
    float near = 0.1f;
    float far = 50.0f;  // where the last cascade ends: the projection's far plane, or nearer (fitted)
};

struct CascadeSettings {
    uint32_t count = 3;       // cascades, 1..kMaxCascades
    uint32_t mapSize = 2048;  // texels along each side of a cascade's shadow map, at least 16
    float lambda = 0.95f;     // splits: 0 uniform, 1 logarithmic (GPU Gems 3, ch. 10)
    // Without depth clamping (a device that lacks it), casters between the light and a cascade's
    // box would be clipped away: with reachCasters, each box reaches toward the light as far as
    // the casters' bounds (the scene's) do.
    bool reachCasters = false;
    glm::vec3 castersMin{0.0f}, castersMax{0.0f};
};
inline constexpr uint32_t kMaxCascades = 4;

// One cascade: the light's camera for one slice of the view, and where the slice ends.
struct Cascade {
    glm::mat4 view{1.0f};        // world -> light view
    glm::mat4 projection{1.0f};  // light view -> clip, orthographic, depth 0..1, snapped to texels
    glm::mat4 viewProjection{1.0f};
    float splitNear = 0.0f;  // the slice's view distances (along -z of the camera's view)
    float splitFar = 0.0f;
    glm::vec3 center{0.0f};  // the slice's bounding sphere, world space
    float radius = 0.0f;
    float texel = 0.0f;  // a shadow-map texel's size in the world
    // The box in whole texels of the light's view: its first column and row (x, y of the light's
    // view divided by `texel`). Two cascades with the same view, texel and depth window whose
    // origins differ by (dx, dy) see the same world shifted by whole texels (shadow_cache.hpp).
    glm::i64vec2 origin{0};
    // The box's depth window: distances along the light from the light view's origin (near: depth
    // 0, far: depth 1). It moves in steps, not with every texel the camera moves (computeCascades).
    float depthNear = 0.0f, depthFar = 0.0f;
};

// count + 1 view distances, near first and far last, each split between a logarithmic and a
// uniform split by `lambda`. Strictly increasing for 0 < near < far.
std::vector<float> cascadeSplits(float near, float far, uint32_t count, float lambda);

// The up vector for a camera looking along `direction` (not zero): of the y and z axes, the one
// less parallel to it, so that their cross product is never near zero (at worst |cross| = 1/sqrt(2)).
glm::vec3 lightUp(glm::vec3 direction);

// The eight corners of the view between view distances `from` and `to`, world space (near four,
// then far four).
std::vector<glm::vec3> sliceCorners(const CascadeCamera& camera, float from, float to);

// The cascades for `camera` and a directional light travelling along `lightDirection` (not zero).
// Each cascade's projection covers its slice's bounding sphere (radius rounded up to 1/16, so the
// projection keeps its size while the camera turns), its centre rounded to whole texels in the
// light's view: every fixed point of the world falls on the same place of a texel whatever the
// camera's position (shadow edges stay still as the camera moves), and a camera that moves less
// than a texel gets the very same matrices (the shadow pass keeps what it drew). The depth window
// holds the sphere with half a radius to spare, placed on a grid of half radii along the light:
// it stays put while the camera moves within a step, so the depths a cascade keeps stay valid.
std::vector<Cascade> computeCascades(const CascadeCamera& camera, glm::vec3 lightDirection,
                                     const CascadeSettings& settings);

// The view distance at which the scene's bounds end, seen from `view`: the farthest of the box's
// corners in front of the camera, rounded up to a step of 2^(1/8) from `near` (so that it moves
// in steps, not with every move of the camera), and at most `far`. A scene that ends before the
// projection's far plane needs no cascades beyond it. `far` itself unless 0 < near < far.
float fittedFar(const glm::mat4& view, glm::vec3 boundsMin, glm::vec3 boundsMax, float near, float far);

// The cascades as passes that rasterise the scene, for common::checkFrameCost: each a mapSize
// square, depth-clamped (nothing clipped in depth), sharing common::kMaxShadowFragments.
std::vector<common::RasterView> cascadeRasterViews(const std::vector<Cascade>& cascades, uint32_t mapSize);
