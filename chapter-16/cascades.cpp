// chapter-16: the cascades of a directional light's shadow.
#include "cascades.hpp"

#include "common/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

//> cascade-splits
std::vector<float> cascadeSplits(float near, float far, uint32_t count, float lambda) {
    std::vector<float> splits(count + 1);
    splits[0] = near;
    for (uint32_t i = 1; i < count; ++i) {
        // p of the way from near to far: logarithmically (each cascade as many times deeper than
        // the one before) and uniformly, mixed by lambda. In double: far / near may be 1e5.
        double p = double(i) / double(count);
        double logarithmic = double(near) * std::pow(double(far) / double(near), p);
        double uniform = double(near) + (double(far) - double(near)) * p;
        splits[i] = float(double(lambda) * logarithmic + (1.0 - double(lambda)) * uniform);
    }
    splits[count] = far;  // exactly: the last cascade ends where the view does
    return splits;
}
//< cascade-splits

//> light-up
glm::vec3 lightUp(glm::vec3 direction) {
    // The book switches to z only when |dot(direction, y)| is exactly 1: a light a hair off
    // vertical keeps y, and lookAt's cross product of two nearly parallel vectors is nearly zero
    // (its normalisation then amplifies rounding into a random frame). Taking the axis of the
    // smaller |dot| keeps the two at least 45 degrees apart.
    glm::vec3 d = glm::normalize(direction);
    return std::abs(d.y) <= std::abs(d.z) ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
}
//< light-up

std::vector<glm::vec3> sliceCorners(const CascadeCamera& camera, float from, float to) {
    // In view space a corner at view distance d is (+-d tan(fovY/2) aspect, +-d tan(fovY/2), -d):
    // no inverse of the projection, whose far plane may be 1e5 times its near one.
    glm::mat4 toWorld = glm::inverse(camera.view);
    float tanY = std::tan(camera.fovY * 0.5f), tanX = tanY * camera.aspect;
    std::vector<glm::vec3> corners;
    for (float d : {from, to})
        for (glm::vec2 sign : {glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)})
            corners.push_back(glm::vec3(toWorld * glm::vec4(sign.x * d * tanX, sign.y * d * tanY, -d, 1.0f)));
    return corners;
}

//> compute-cascades
std::vector<Cascade> computeCascades(const CascadeCamera& camera, glm::vec3 lightDirection,
                                     const CascadeSettings& settings) {
    std::vector<float> splits = cascadeSplits(camera.near, camera.far, settings.count, settings.lambda);
    // The light's view: a rotation only (its eye at the world's origin, looking along the light),
    // the same for every cascade and every camera position. Each cascade's box is placed in it.
    glm::vec3 direction = glm::normalize(lightDirection);
    glm::mat4 lightView = glm::lookAt(glm::vec3(0.0f), direction, lightUp(direction));
    std::vector<Cascade> cascades(settings.count);
    for (uint32_t i = 0; i < settings.count; ++i) {
        Cascade& cascade = cascades[i];
        cascade.splitNear = splits[i];
        cascade.splitFar = splits[i + 1];
        // The slice's bounding sphere: centred on its corners' mean, radius rounded up to 1/16
        // so that it changes only in steps as the camera turns (the projection's scale, and so
        // the size of a texel in the world, stays put between the steps).
        std::vector<glm::vec3> corners = sliceCorners(camera, cascade.splitNear, cascade.splitFar);
        glm::vec3 center(0.0f);
        for (const glm::vec3& corner : corners) center += corner / 8.0f;
        float radius = 0.0f;
        for (const glm::vec3& corner : corners) radius = std::max(radius, glm::length(corner - center));
        radius = std::ceil(radius * 16.0f) / 16.0f;
        cascade.center = center;
        cascade.radius = radius;

        // Texel snapping: the sphere's centre, in the light's view, rounded to whole texels. The
        // box around it is the sphere's square plus one texel on every side -- the rounding moves
        // it by at most half a texel -- so every fixed point of the world falls on the same place
        // of a texel wherever the camera is, and while the camera moves within a texel the
        // cascade's matrix does not change at all (the shadow pass can keep the layer). The book
        // rounds the origin's position in the light's view in world units, which does not snap
        // to texels.
        float texel = 2.0f * radius / float(settings.mapSize - 2);  // a texel's size in the world
        float half = radius + texel;                                // mapSize / 2 texels
        glm::vec3 c = glm::vec3(lightView * glm::vec4(center, 1.0f));
        glm::vec2 index = glm::round(glm::vec2(c) / texel);  // whole texels
        c = glm::vec3(index * texel, c.z);
        cascade.texel = texel;
        cascade.view = lightView;
        cascade.origin = glm::i64vec2(std::llround(double(index.x)), std::llround(double(index.y))) -
                         int64_t(settings.mapSize / 2);
        // Depth: 0 at the window's side toward the light, 1 at its far side; the view looks along
        // -z, so the sphere spans distances -c.z - half to -c.z + half. The window is the
        // sphere's extent plus a step (half of half), starting on a multiple of that step: as
        // the camera moves, the window moves only when the sphere leaves it, and a cascade
        // redrawn for its scrolling keeps the same depths for the same casters. Casters between
        // the light and the window are kept by depth clamping (the shadow pipeline).
        double step = 0.5 * double(half);
        double nearest = std::floor((double(-c.z) - double(half)) / step) * step;
        float near = float(nearest), far = float(nearest + 2.0 * double(half) + step);
        if (settings.reachCasters)
            for (int k = 0; k < 8; ++k) {
                glm::vec3 corner = common::boxCorner(k, settings.castersMin, settings.castersMax);
                near = std::min(near, -(lightView * glm::vec4(corner, 1.0f)).z - texel);
            }
        cascade.depthNear = near;
        cascade.depthFar = far;
        cascade.projection = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, near, far);
        cascade.viewProjection = cascade.projection * cascade.view;
    }
    return cascades;
}
//< compute-cascades

//> fitted-far
float fittedFar(const glm::mat4& view, glm::vec3 boundsMin, glm::vec3 boundsMax, float near, float far) {
    if (!(near > 0.0f) || !(far > near)) return far;  // no steps from a near plane at or past 0
    float farthest = near;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner = common::boxCorner(i, boundsMin, boundsMax);
        farthest = std::max(farthest, -(view * glm::vec4(corner, 1.0f)).z);  // view distance
    }
    if (!(farthest < far)) return far;
    // Rounded up to the next of near x 2^(k/8): the far plane -- and with it every split, sphere and
    // texel -- changes only when the camera has moved far enough to cross a step, not every frame
    // (which would undo the snapping). At most 9% more than the scene needs.
    double steps = std::ceil(8.0 * std::log2(double(farthest) / double(near)));
    return float(std::min(double(far), double(near) * std::exp2(steps / 8.0)));
}
//< fitted-far

std::vector<common::RasterView> cascadeRasterViews(const std::vector<Cascade>& cascades, uint32_t mapSize) {
    std::vector<common::RasterView> views;
    for (size_t i = 0; i < cascades.size(); ++i)
        views.push_back({.name = "shadow cascade " + std::to_string(i),
                         .viewProjection = cascades[i].viewProjection,
                         .width = mapSize,
                         .height = mapSize,
                         .clipDepth = false,
                         .budget = common::kMaxShadowFragments / cascades.size()});
    return views;
}
