// Unit tests of the book's light controls (common/app/light_controls.cpp): turning the sun keeps
// its heading, and a sun in the y-z plane keeps the book's angle about the x axis.
#include <gtest/gtest.h>

#include <cmath>

#include "common/app/light_controls.hpp"

namespace {

common::Scene sceneWithSun(glm::vec3 direction) {
    common::Scene scene;
    scene.lights.push_back({.type = common::Light::Type::Directional, .direction = direction});
    return scene;
}

void expectParallel(glm::vec3 a, glm::vec3 b) {
    glm::vec3 na = glm::normalize(a), nb = glm::normalize(b);
    EXPECT_NEAR(na.x, nb.x, 1e-5f);
    EXPECT_NEAR(na.y, nb.y, 1e-5f);
    EXPECT_NEAR(na.z, nb.z, 1e-5f);
}

TEST(LightControls, TurningTheSunKeepsItsHeading) {
    common::Scene scene = sceneWithSun({1.0f, -1.0f, 0.5f});
    common::LightControls controls = common::findControlledLights(scene);
    ASSERT_EQ(controls.sun, 0);
    common::setSunAngle(controls, scene, controls.sunAngle);  // the first touch: nothing moves
    expectParallel(scene.lights[0].direction, {1.0f, -1.0f, 0.5f});
    common::setSunAngle(controls, scene, 300.0f);  // higher or lower, but still from the side
    glm::vec3 d = scene.lights[0].direction;
    EXPECT_NEAR(d.x / d.z, 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    common::setSunAngle(controls, scene, 270.0f);
    expectParallel(scene.lights[0].direction, {0.0f, -1.0f, 0.0f});
}

TEST(LightControls, ASunInTheYZPlaneKeepsTheBooksAngle) {
    common::Scene scene = sceneWithSun({0.0f, -1.0f, -0.5f});
    common::LightControls controls = common::findControlledLights(scene);
    EXPECT_NEAR(controls.sunAngle, 360.0f + glm::degrees(std::atan2(-1.0f, -0.5f)), 1e-3f);  // 243.4
    common::setSunAngle(controls, scene, 250.0f);
    float r = glm::radians(250.0f);
    expectParallel(scene.lights[0].direction, {0.0f, std::sin(r), std::cos(r)});
}

TEST(LightControls, ASunStraightDownTurnsInTheBooksPlane) {
    common::Scene scene = sceneWithSun({0.0f, -2.0f, 0.0f});
    common::LightControls controls = common::findControlledLights(scene);
    EXPECT_NEAR(controls.sunAngle, 270.0f, 1e-4f);
    common::setSunAngle(controls, scene, 180.0f);
    expectParallel(scene.lights[0].direction, {0.0f, 0.0f, -1.0f});
    common::setSunAngle(controls, scene, 400.0f);  // clamped to the horizon ahead
    expectParallel(scene.lights[0].direction, {0.0f, 0.0f, 1.0f});
}

TEST(LightControls, ASunAlongOrAboveTheHorizonStartsInTheControlsRange) {
    // Along the horizon ahead: 360, not 0, so the first touch does not swing it to the far horizon.
    for (glm::vec3 direction : {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(1.0f, 0.0f, 0.0f)}) {
        common::Scene scene = sceneWithSun(direction);
        common::LightControls controls = common::findControlledLights(scene);
        EXPECT_EQ(controls.sunAngle, 360.0f);
        common::setSunAngle(controls, scene, controls.sunAngle);
        expectParallel(scene.lights[0].direction, direction);
    }
    // Pointing up, outside the controls' range: it starts at the nearer horizon.
    common::Scene up = sceneWithSun({0.0f, 1.0f, 1.0f});
    EXPECT_EQ(common::findControlledLights(up).sunAngle, 360.0f);
    common::Scene upBehind = sceneWithSun({0.0f, 1.0f, -1.0f});
    EXPECT_EQ(common::findControlledLights(upBehind).sunAngle, 180.0f);
}

}  // namespace
