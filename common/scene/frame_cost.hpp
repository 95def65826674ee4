// What a frame may cost to rasterise, bounded before the first frame is drawn. A model's budget
// (common/model/model.hpp) counts triangles; what they cost the rasteriser is the area they cover, in
// the view and in each shadow cascade: 2,000 stacked quads that each cover the view are 4,000
// triangles and 2,000 layers of fragments, in every pass. A chapter adds up, triangle by
// triangle, an upper bound of the fragments its first frame rasterises -- each triangle's area in
// pixels in each pass that draws it, plus its perimeter and one (a triangle covers no more pixel
// centres than that; nor more than its bounding box on the target) -- and refuses a scene whose
// bound passes a view's budget in one line (docs/reliability.md, "What a frame may cost").
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/model/load_model.hpp"
#include "common/model/model.hpp"
#include "common/scene/scene.hpp"

namespace common {

// One pass that rasterises the scene's triangles: the view, or a shadow cascade.
struct RasterView {
    std::string name;                // for the message: "view", "cascade 0"
    glm::mat4 viewProjection{1.0f};  // world -> clip (Vulkan's: depth 0..1)
    uint32_t width = 0, height = 0;  // its target, pixels or texels
    // A perspective view clips triangles at its near plane and drops those wholly beyond its far
    // plane; a depth-clamped orthographic cascade clips nothing in depth.
    bool clipDepth = true;
    uint64_t budget = 0;  // the most fragments the bound may reach in this view
};

// The budgets. The view: on average 64 fragments a pixel (59 million at 1280x720; chapter-15's
// scene pass shades some 34 million a second on lavapipe on two cores: under 2 s, while a real
// scene bounds at a few a pixel -- chapter-15's default scene at 2.2). The shadow cascades: 2^31
// fragments together, whatever their number and size (chapter-16's shadow pass rasterises some
// 0.8e9 a second on lavapipe: under 3 s). docs/reliability.md has the measurements.
// Small targets get at least 2^24 (a triangle that covers no pixel centre still counts one in
// the bound, and 16 million fragments are under half a second of lavapipe).
inline constexpr uint64_t kMaxViewFragmentsPerPixel = 64;
inline constexpr uint64_t kMinViewFragments = uint64_t{1} << 24;
inline constexpr uint64_t kMaxShadowFragments = uint64_t{1} << 31;
// Triangles drawn a frame, every placed model times its triangles (repeats included): 2^25, the
// most one model may have. Checked first, from the counts alone, so that the bound's own work
// (each triangle in each view) is bounded too.
inline constexpr uint64_t kMaxFrameTriangles = uint64_t{1} << 25;

struct FrameCost {
    std::vector<uint64_t> fragments;  // per view, an upper bound (saturating)
    bool over = false;                // some view's bound passed its budget: the count stopped there
    size_t overView = 0;              // which
    size_t lastModel = 0;             // the scene's model being counted when it stopped
};

// The bound for `scene` (its models from `models`, every placed mesh and repeat, as loadGpuScene
// draws them) in each of `views`. Stops counting once a view passes its budget: the work is at
// most the scene's triangles times the views.
FrameCost frameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views);

// The view of the scene's camera (its place, yaw, pitch, field of view, near and far) on a
// width x height target: what the first frame's scene pass draws, with its budget.
RasterView sceneRasterView(const Scene& scene, uint32_t width, uint32_t height);

// Throws InputError naming the view whose bound passed its budget, and the model that did it;
// returns the bound otherwise.
FrameCost checkFrameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views);

}  // namespace common
