// What a frame may cost to rasterise (frame_cost.hpp).
#include "common/scene/frame_cost.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"

namespace common {

namespace {

// Pixels a triangle (clip-space corners) may cover on a width x height target: its area plus its
// perimeter plus one, in pixels, after clipping at the near plane, and at most the pixel centres
// of its bounding box within the target. A pixel counts when its centre is inside; the unit squares around
// those centres lie in the triangle grown by half a pixel, whose area is at most area + 0.71 x perimeter + 1.
double trianglePixels(const glm::dvec4 (&corner)[3], double width, double height, bool clipDepth) {
    glm::dvec4 polygon[4];
    int count = 0;
    if (clipDepth) {
        bool beyondFar = true;
        for (const glm::dvec4& c : corner) beyondFar = beyondFar && c.z > c.w;
        if (beyondFar) return 0.0;
        // Clipped against z >= 0 (Vulkan's near plane): a triangle gives at most four corners.
        for (int i = 0; i < 3; ++i) {
            const glm::dvec4 &a = corner[i], &b = corner[(i + 1) % 3];
            if (a.z >= 0.0) polygon[count++] = a;
            if ((a.z >= 0.0) != (b.z >= 0.0)) {
                double t = a.z / (a.z - b.z);
                polygon[count++] = a + (b - a) * t;
            }
        }
        if (count < 3) return 0.0;
    } else {
        for (int i = 0; i < 3; ++i) polygon[count++] = corner[i];
    }
    glm::dvec2 p[4];
    glm::dvec2 low(INFINITY), high(-INFINITY);
    for (int i = 0; i < count; ++i) {
        double w = polygon[i].w;
        // A corner on the eye's plane (w = 0 after clipping at z = 0 with a zero near plane): its
        // place on the target is unbounded; the bounding box bounds the triangle.
        if (!(std::abs(w) > 1e-300)) return width * height;
        p[i] = glm::dvec2((polygon[i].x / w * 0.5 + 0.5) * width, (polygon[i].y / w * 0.5 + 0.5) * height);
        low = glm::min(low, p[i]);
        high = glm::max(high, p[i]);
    }
    // The pixel centres (k + 0.5) of the target in the bounding box, the box grown by 1/16 of a
    // pixel (the coarsest sub-pixel precision Vulkan allows: where a vertex may snap to). None: the
    // triangle covers no pixel (off the target, between two centres, or not a number).
    auto centres = [](double lo, double hi, double size) {
        constexpr double kSnap = 1.0 / 16.0;
        double first = std::max(0.0, std::ceil(lo - 0.5 - kSnap));
        double last = std::min(size - 1.0, std::floor(hi - 0.5 + kSnap));
        return last >= first ? last - first + 1.0 : 0.0;
    };
    double box = centres(low.x, high.x, width) * centres(low.y, high.y, height);
    if (!(box > 0.0)) return 0.0;
    double area = 0.0, perimeter = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 &a = p[i], &b = p[(i + 1) % count];
        area += a.x * b.y - b.x * a.y;
        perimeter += glm::length(b - a);
    }
    double bound = std::abs(area) * 0.5 + perimeter + 1.0;
    return std::min({box, bound, width * height});
}

}  // namespace

FrameCost frameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views) {
    FrameCost cost;
    cost.fragments.assign(views.size(), 0);
    std::vector<double> sums(views.size(), 0.0);
    std::vector<glm::dvec4> clip;
    for (size_t index = 0; index < scene.models.size(); ++index) {
        const ModelInstance& instance = scene.models[index];
        cost.lastModel = index;
        const ModelData& model = loadModelCached(models, instance.file);
        const glm::dmat4 placed(instance.transform.matrix());
        // Each mesh as many times as it is drawn: once, and once more per repeat.
        std::vector<uint32_t> draws(model.meshes.size(), 1);
        for (const MeshRepeat& repeat : model.repeats) draws.at(repeat.mesh) += 1;
        for (size_t v = 0; v < views.size(); ++v) {
            const RasterView& view = views[v];
            const glm::dmat4 toClip = glm::dmat4(view.viewProjection) * placed;
            for (size_t m = 0; m < model.meshes.size(); ++m) {
                const MeshData& mesh = model.meshes[m];
                clip.resize(mesh.vertices.size());
                for (size_t i = 0; i < mesh.vertices.size(); ++i)
                    clip[i] = toClip * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0);
                double pixels = 0.0;
                for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
                    const glm::dvec4 corner[3] = {clip[mesh.indices[k]], clip[mesh.indices[k + 1]],
                                                  clip[mesh.indices[k + 2]]};
                    pixels += trianglePixels(corner, view.width, view.height, view.clipDepth);
                }
                pixels *= draws[m];
                sums[v] += pixels;
                if (sums[v] > double(view.budget)) {
                    cost.over = true;
                    cost.overView = v;
                    break;
                }
            }
            if (cost.over) break;
        }
        if (cost.over) break;
    }
    for (size_t v = 0; v < views.size(); ++v)
        cost.fragments[v] = sums[v] >= 1.8e19 ? UINT64_MAX : uint64_t(sums[v]);
    return cost;
}

RasterView sceneRasterView(const Scene& scene, uint32_t width, uint32_t height) {
    const CameraDesc& camera = scene.camera;
    glm::mat4 view = viewMatrix(Camera{camera.position, camera.yaw, camera.pitch});
    glm::mat4 projection = projectionMatrix(camera.fov, VkExtent2D{width, height}, camera.near, camera.far);
    return RasterView{.name = "the view",
                      .viewProjection = projection * view,
                      .width = width,
                      .height = height,
                      .budget = std::max(kMaxViewFragmentsPerPixel * width * height, kMinViewFragments)};
}

FrameCost checkFrameCost(const Scene& scene, ModelCache& models, std::span<const RasterView> views) {
    uint64_t triangles = 0;
    for (size_t index = 0; index < scene.models.size(); ++index) {
        const ModelData& model = loadModelCached(models, scene.models[index].file);
        for (const MeshData& mesh : model.meshes) triangles += mesh.indices.size() / 3;
        for (const MeshRepeat& repeat : model.repeats)
            triangles += model.meshes.at(repeat.mesh).indices.size() / 3;
        if (triangles > kMaxFrameTriangles)
            throw InputError(utf8(scene.models[index].file) + ": the scene places it as model " +
                             std::to_string(index) + ", past " + std::to_string(kMaxFrameTriangles) +
                             " triangles drawn a frame in all (models times their triangles)");
    }
    FrameCost cost = frameCost(scene, models, views);
    if (!cost.over) return cost;
    const RasterView& view = views[cost.overView];
    char text[400];
    std::snprintf(text, sizeof(text),
                  ": its triangles cover %s many times over: the first frame would rasterise more than "
                  "%llu fragments there, the budget of a %ux%u target (counted triangle by triangle; "
                  "model %zu of the scene)",
                  view.name.c_str(), static_cast<unsigned long long>(view.budget), view.width, view.height,
                  cost.lastModel);
    throw InputError(utf8(scene.models[cost.lastModel].file) + text);
}

}  // namespace common
