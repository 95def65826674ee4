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

        // Texel snapping: the sphere's centre, in the light's view, rounded to whole texels (depth
        // too). The box around it is the sphere's square plus one texel on every side -- the
        // rounding moves it by at most half a texel -- so every fixed point of the world falls on
        // the same place of a texel wherever the camera is, and while the camera moves within a
        // texel the cascade's matrix does not change at all (the shadow pass can keep the layer).
        // The book rounds the origin's position in the light's view in world units, which does
        // not snap to texels. Depth: 0 at the box's side toward the light, 1 at the far side;
        // casters between the light and the box are kept by depth clamping (the shadow pipeline).
        float texel = 2.0f * radius / float(settings.mapSize - 2);  // a texel's size in the world
        float half = radius + texel;
        glm::vec3 c = glm::vec3(lightView * glm::vec4(center, 1.0f));
        c = glm::round(c / texel) * texel;
        cascade.texel = texel;
        cascade.view = lightView;
        // The view looks along -z: the box spans z from c.z + half (toward the light) to c.z - half.
        float near = -c.z - half;
        if (settings.reachCasters)
            for (int k = 0; k < 8; ++k) {
                glm::vec3 corner((k & 1) ? settings.castersMax.x : settings.castersMin.x,
                                 (k & 2) ? settings.castersMax.y : settings.castersMin.y,
                                 (k & 4) ? settings.castersMax.z : settings.castersMin.z);
                near = std::min(near, -(lightView * glm::vec4(corner, 1.0f)).z - texel);
            }
        cascade.projection = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, near, -c.z + half);
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
