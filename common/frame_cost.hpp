// What a frame may cost to rasterise, bounded before the first frame is drawn. A model's budget
// (common/model.hpp) counts triangles; what they cost the rasteriser is the area they cover, in
// the view and in each shadow cascade: 2,000 stacked quads that each cover the view are 4,000
// triangles and 2,000 layers of fragments, in every pass. A chapter adds up, triangle by
// triangle, an upper bound of the fragments its first frame rasterises -- each triangle's area in
// pixels in each pass that draws it, plus its perimeter and one (a triangle covers no more pixel
// centres than that; nor more than its bounding box on the target) -- and refuses a scene beyond
// kMaxFrameFragments in one line (docs/reliability.md, "What a frame may cost").
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/model.hpp"
#include "common/scene.hpp"

namespace common {

// One pass that rasterises the scene's triangles: the view, or a shadow cascade.
struct RasterView {
    std::string name;            // for the message: "view", "cascade 0"
    glm::mat4 viewProjection{1.0f};  // world -> clip (Vulkan's: depth 0..1)
    uint32_t width = 0, height = 0;  // its target, pixels or texels
    // A perspective view clips triangles at its near plane and drops those wholly beyond its far
    // plane; a depth-clamped orthographic cascade clips nothing in depth.
    bool clipDepth = true;
};

// At most 2^31 fragments a frame (the bound, not what the GPU finally shades): about 3 s of
// lavapipe on two cores, where chapter-16's shadow pass rasterises some 0.67e9 of the bound a
// second, and milliseconds on a desktop GPU. chapter-16's default scene at 1280x720 bounds at 13
// million (docs/reliability.md has the scenes' figures).
inline constexpr uint64_t kMaxFrameFragments = uint64_t{1} << 31;

struct FrameCost {
    std::vector<uint64_t> fragments;  // per view, an upper bound (saturating)
    uint64_t total = 0;
    bool over = false;     // total > limit: the count stopped there
    size_t lastModel = 0;  // the scene's model being counted when it stopped
};

// The bound for `scene` (its models from `models`, every placed mesh and repeat, as loadGpuScene
// draws them) in each of `views`. Stops counting once the total passes `limit`: the work is at
// most the scene's triangles times the views.
FrameCost frameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views,
                    uint64_t limit = kMaxFrameFragments);

// The view of the scene's camera (its place, yaw, pitch, field of view, near and far) on a
// width x height target: what the first frame's scene pass draws.
RasterView sceneRasterView(const Scene& scene, uint32_t width, uint32_t height);

// Throws InputError naming the costliest view when the bound passes kMaxFrameFragments;
// returns the bound otherwise.
FrameCost checkFrameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views);

}  // namespace common
