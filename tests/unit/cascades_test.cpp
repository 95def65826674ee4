// chapter-16's cascade math (chapter-16/cascades.cpp): the splits, every slice inside its cascade,
// texel snapping that moves the shadow map by whole texels, and finite matrices for any light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "chapter-16/cascades.hpp"

namespace {

// A camera at `position` looking along yaw/pitch (degrees), as common::viewMatrix makes it.
CascadeCamera camera(glm::vec3 position, float yaw, float pitch, float near = 0.5f, float far = 50.0f) {
    glm::vec3 forward(std::cos(glm::radians(pitch)) * std::cos(glm::radians(yaw)),
                      std::sin(glm::radians(pitch)),
                      std::cos(glm::radians(pitch)) * std::sin(glm::radians(yaw)));
    CascadeCamera c;
    c.view = glm::lookAt(position, position + forward, glm::vec3(0.0f, 1.0f, 0.0f));
    c.fovY = glm::radians(60.0f);
    c.aspect = 16.0f / 9.0f;
    c.near = near;
    c.far = far;
    return c;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Where `point` falls in cascade `cascade`'s shadow map, in texels (x, y).
glm::dvec2 texels(const Cascade& cascade, glm::vec3 point, uint32_t mapSize) {
    glm::vec4 clip = cascade.viewProjection * glm::vec4(point, 1.0f);
    return glm::dvec2(clip.x, clip.y) * (double(mapSize) * 0.5);
}

}  // namespace

TEST(Cascades, SplitsIncreaseFromNearToFar) {
    for (auto [near, far] : {std::pair{0.5f, 50.0f}, {0.01f, 1000.0f}, {0.1f, 0.2f}, {1.0f, 1e5f}})
        for (uint32_t count = 1; count <= kMaxCascades; ++count)
            for (float lambda : {0.0f, 0.5f, 0.95f, 1.0f}) {
                std::vector<float> splits = cascadeSplits(near, far, count, lambda);
                ASSERT_EQ(splits.size(), count + 1);
                EXPECT_EQ(splits.front(), near);
                EXPECT_EQ(splits.back(), far);
                for (uint32_t i = 1; i <= count; ++i) {
                    EXPECT_TRUE(std::isfinite(splits[i]));
                    EXPECT_GT(splits[i], splits[i - 1]) << near << ".." << far << " count " << count
                                                        << " lambda " << lambda << " split " << i;
                }
            }
    // The book's settings: lambda 0.95 between 0.5 and 50 puts the first split near the camera.
    std::vector<float> book = cascadeSplits(0.5f, 50.0f, 3, 0.95f);
    EXPECT_NEAR(book[1], 0.95 * 0.5 * std::pow(100.0, 1.0 / 3.0) + 0.05 * (0.5 + 49.5 / 3.0), 1e-4);
}

TEST(Cascades, UpIsNeverNearlyParallelToTheLight) {
    std::mt19937 random(7);
    std::normal_distribution<float> normal;
    std::vector<glm::vec3> directions{{0, -1, 0},     {0, 1, 0}, {0, 0, 1},
                                      {0, 0, -1},     {1, 0, 0}, {std::sin(1e-6f), -std::cos(1e-6f), 0},
                                      {0, -1, 1e-7f}, {0, 1, 1}, {0, -1, -1},
                                      {1e-30f, -1, 0}};
    for (int i = 0; i < 1000; ++i) directions.push_back({normal(random), normal(random), normal(random)});
    for (glm::vec3 d : directions) {
        glm::vec3 up = lightUp(d);
        EXPECT_GE(glm::length(glm::cross(glm::normalize(d), up)), 0.7071f - 1e-5f)
            << d.x << " " << d.y << " " << d.z;
    }
}

TEST(Cascades, EverySliceCornerIsInsideItsCascade) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> angle(-180.0f, 180.0f), pitch(-89.0f, 89.0f), offset(-30.0f, 30.0f);
    for (int trial = 0; trial < 200; ++trial) {
        CascadeCamera c = camera({offset(random), offset(random) * 0.2f, offset(random)}, angle(random),
                                 pitch(random), trial % 2 ? 0.5f : 0.01f, trial % 2 ? 50.0f : 1000.0f);
        glm::vec3 light(std::cos(glm::radians(angle(random))), -1.0f - float(trial % 3),
                        std::sin(glm::radians(angle(random))));
        for (uint32_t count : {1u, 3u, 4u})
            for (uint32_t mapSize : {512u, 4096u}) {
                std::vector<Cascade> cascades = computeCascades(c, light, {count, mapSize, 0.95f});
                ASSERT_EQ(cascades.size(), count);
                for (const Cascade& cascade : cascades) {
                    ASSERT_TRUE(finite(cascade.viewProjection));
                    // Inside by at least half a texel in x and y; in 0..1 in depth.
                    double margin = 1.0 / mapSize;
                    for (glm::vec3 corner : sliceCorners(c, cascade.splitNear, cascade.splitFar)) {
                        glm::vec4 clip = cascade.viewProjection * glm::vec4(corner, 1.0f);
                        EXPECT_LE(std::abs(clip.x), 1.0 - margin + 1e-5) << "trial " << trial;
                        EXPECT_LE(std::abs(clip.y), 1.0 - margin + 1e-5) << "trial " << trial;
                        EXPECT_GE(clip.z, -1e-5f) << "trial " << trial;
                        EXPECT_LE(clip.z, 1.0f + 1e-5f) << "trial " << trial;
                    }
                }
            }
    }
}

// The camera moved by less than a texel, and by many: every fixed point of the world moves in the
// shadow map by the same whole number of texels (so a shadow edge's texels stay the same texels).
TEST(Cascades, SnappingMovesTheMapByWholeTexels) {
    const uint32_t mapSize = 2048;
    glm::vec3 light(0.3f, -1.0f, 0.2f);
    CascadeCamera a = camera({1.0f, 2.0f, 3.0f}, 30.0f, -20.0f);
    std::vector<glm::vec3> points{{0, 0, 0}, {5, 1, -3}, {-7.3f, 0.2f, 11.9f}, {2.5f, 4, 8}};
    for (glm::vec3 move :
         {glm::vec3(0.0013f, 0, 0), glm::vec3(0.0071f, -0.003f, 0.0119f), glm::vec3(3.7f, 0.2f, -1.9f)}) {
        CascadeCamera b = camera(glm::vec3(1.0f, 2.0f, 3.0f) + move, 30.0f, -20.0f);
        std::vector<Cascade> ca = computeCascades(a, light, {3, mapSize, 0.95f});
        std::vector<Cascade> cb = computeCascades(b, light, {3, mapSize, 0.95f});
        for (size_t i = 0; i < ca.size(); ++i) {
            ASSERT_EQ(ca[i].radius, cb[i].radius);  // translation only: the same texel size
            glm::dvec2 shift = texels(cb[i], points[0], mapSize) - texels(ca[i], points[0], mapSize);
            EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3) << "cascade " << i;
            EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3) << "cascade " << i;
            for (glm::vec3 p : points) {
                glm::dvec2 s = texels(cb[i], p, mapSize) - texels(ca[i], p, mapSize);
                EXPECT_NEAR(s.x, shift.x, 2e-3) << "cascade " << i;
                EXPECT_NEAR(s.y, shift.y, 2e-3) << "cascade " << i;
            }
        }
    }
}

TEST(Cascades, FiniteForAnyLightDirectionAndCamera) {
    std::vector<glm::vec3> lights{{0, -1, 0},      {std::sin(1e-6f), -std::cos(1e-6f), 0},
                                  {0, 1, 0},       {0, 0, -1},
                                  {0, -1, 1e-7f},  {1, -0.0174f, 0},
                                  {1e-30f, -1, 0}, {0, -1, -1}};
    for (float pitch : {-89.0f, 89.0f, 0.0f})  // straight down, straight up (as far as the camera turns)
        for (glm::vec3 light : lights) {
            std::vector<Cascade> cascades =
                computeCascades(camera({0, 1, 0}, 90.0f, pitch), light, {4, 1024, 0.95f});
            for (const Cascade& cascade : cascades) {
                ASSERT_TRUE(finite(cascade.viewProjection)) << light.x << " " << light.y << " " << light.z;
                // The light's view is a rotation: its 3x3 part orthonormal (no degenerate frame).
                glm::mat3 r(cascade.view);
                EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-4f);
                EXPECT_NEAR(glm::length(r[0]), 1.0f, 1e-4f);
                EXPECT_NEAR(glm::dot(r[0], r[1]), 0.0f, 1e-4f);
            }
        }
}

TEST(Cascades, FittedFarEndsWhereTheSceneEndsInSteps) {
    glm::mat4 view = camera({0, 1, 10}, -90.0f, 0.0f).view;  // at z = 10 looking down -z
    // A box from z = -2 to 2: the farthest corner 12 away; the next step 0.5 x 2^(37/8) = 12.34.
    float far = fittedFar(view, {-1, 0, -2}, {1, 2, 2}, 0.5f, 50.0f);
    EXPECT_NEAR(far, 0.5 * std::exp2(37.0 / 8.0), 1e-3);
    EXPECT_GE(far, 12.0f);
    // Larger than the view: the projection's far plane.
    EXPECT_EQ(fittedFar(view, {-100, -100, -100}, {100, 100, 100}, 0.5f, 50.0f), 50.0f);
    // Wholly behind the camera: nothing to cover beyond the near plane.
    EXPECT_EQ(fittedFar(view, {-1, 0, 20}, {1, 1, 30}, 0.5f, 50.0f), 0.5f);
    // Steps: a camera moving toward the scene by 1 cm at a time changes the far plane a few times
    // over 3 m, never by less than a step, and always covers the scene within 9%.
    float last = 0.0f;
    int changes = 0;
    for (int i = 0; i < 300; ++i) {
        float z = 10.0f - 0.01f * float(i);
        float f = fittedFar(camera({0, 1, z}, -90.0f, 0.0f).view, {-1, 0, -2}, {1, 2, 2}, 0.5f, 50.0f);
        float needed = z + 2.0f;
        EXPECT_GE(f, needed - 1e-4f);
        EXPECT_LE(f, needed * 1.0906f);
        if (last != 0.0f && f != last) {
            ++changes;
            EXPECT_NEAR(last / f, std::exp2(1.0 / 8.0), 1e-4);
        }
        last = f;
    }
    EXPECT_LE(changes, 4);
}

// A camera moving by less than a texel gets the very same matrices, to the bit: the shadow pass
// keeps what it drew, and shadow edges cannot crawl. Moving by a few texels changes them.
TEST(Cascades, ACameraMovingWithinATexelKeepsItsMatricesToTheBit) {
    const glm::vec3 light(0.3f, -1.0f, 0.2f);
    CascadeCamera a = camera({1.0f, 2.0f, 3.0f}, 30.0f, -20.0f);
    std::vector<Cascade> ca = computeCascades(a, light, {3, 2048, 0.95f});
    int same = 0, steps = 0;
    for (int i = 1; i <= 100; ++i) {
        // 1e-5 of the first cascade's texel at a time, along a slanted line.
        float step = 1e-5f * ca[0].texel * float(i);
        CascadeCamera b =
            camera(glm::vec3(1.0f, 2.0f, 3.0f) + glm::vec3(step, step * 0.5f, -step), 30.0f, -20.0f);
        std::vector<Cascade> cb = computeCascades(b, light, {3, 2048, 0.95f});
        for (size_t k = 0; k < ca.size(); ++k, ++steps)
            if (std::memcmp(&ca[k].viewProjection, &cb[k].viewProjection, sizeof(glm::mat4)) == 0) ++same;
    }
    // A hundred moves of at most a thousandth of a texel: a centre lying within 1e-3 texels of a
    // rounding boundary may cross it; the others must not change.
    EXPECT_GE(same, steps - 6) << same << " of " << steps;
    CascadeCamera far =
        camera(glm::vec3(1.0f, 2.0f, 3.0f) + glm::vec3(5.0f * ca[2].texel, 0, 0), 30.0f, -20.0f);
    std::vector<Cascade> cf = computeCascades(far, light, {3, 2048, 0.95f});
    for (size_t k = 0; k < ca.size(); ++k)
        EXPECT_NE(std::memcmp(&ca[k].viewProjection, &cf[k].viewProjection, sizeof(glm::mat4)), 0) << k;
}

// Near vertical, a light that turns by 1e-6 radians turns its shadow map's frame by about as much.
// With the book's up vector (y unless |dot(light, y)| is exactly 1, which in float happens only
// within about 3e-4 radians of vertical) the frame comes from the cross product of two nearly
// parallel vectors: 5e-4 radians off vertical it turns 2000 times as far as the light, a few
// texels at the edge of a 2048-texel map.
TEST(Cascades, ANearlyVerticalLightHasAStableFrame) {
    CascadeCamera c = camera({0, 2, 5}, -90.0f, -30.0f);
    for (float off : {5e-4f, 1e-3f, 1e-6f, 0.0f}) {
        glm::vec3 base(std::sin(off), -std::cos(off), 0.0f);
        glm::vec3 turned = base + glm::vec3(0.0f, 0.0f, 1e-6f);
        std::vector<Cascade> a = computeCascades(c, base, {3, 2048, 0.95f});
        std::vector<Cascade> b = computeCascades(c, turned, {3, 2048, 0.95f});
        glm::mat3 ra(a[0].view), rb(b[0].view);
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                EXPECT_NEAR(ra[col][row], rb[col][row], 1e-4f) << off << " rad off: " << col << "," << row;
    }
}
