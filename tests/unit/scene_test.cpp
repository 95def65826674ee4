// Unit tests of scene files: every field survives a round trip through JSON; bad files are refused
// with a message that names the offending key.
#include <gtest/gtest.h>

#include <string>

#include "common/core/check.hpp"
#include "common/scene/scene.hpp"

namespace {

common::Scene everyField() {
    common::Scene scene;
    common::ModelInstance a{.file = "/models/a.obj"};
    a.transform = {
        .position = {1.5f, -2.0f, 3.25f}, .rotation = {10.0f, -20.0f, 30.0f}, .scale = {0.5f, 2.0f, 3.0f}};
    a.materials["gold"] = {.diffuse = glm::vec4(1.0f, 0.77f, 0.34f, 0.5f),
                           .roughness = 0.25f,
                           .metallic = 1.0f,
                           .diffuseTexture = std::filesystem::path("/textures/gold.png"),
                           .normalTexture = std::filesystem::path("/textures/gold_n.png")};
    a.materials["plain"] = {.roughness = 0.75f};
    scene.models.push_back(a);
    scene.models.push_back({.file = "/models/b.obj"});
    scene.camera = {
        .position = {4, 5, 6}, .yaw = 45.0f, .pitch = -30.0f, .fov = 75.0f, .near = 0.5f, .far = 500.0f};
    scene.ambientColor = {0.1f, 0.2f, 0.3f};
    scene.ambientIntensity = 0.4f;
    scene.lights.push_back({.type = common::Light::Type::Directional,
                            .direction = {0, -1, 0.5f},
                            .color = {1, 0.9f, 0.8f},
                            .intensity = 3.0f});
    scene.lights.push_back({.type = common::Light::Type::Point,
                            .position = {5, 3.4f, 1.2f},
                            .color = {0, 1, 0},
                            .intensity = 10.0f,
                            .marker = 1,
                            .range = 7.5f});
    return scene;
}

TEST(SceneJson, RoundTripKeepsEveryField) {
    common::Scene scene = everyField();
    std::string json = common::sceneToJson(scene);
    common::Scene back = common::parseScene(json, "test", "/");
    EXPECT_EQ(back, scene) << json;
    EXPECT_EQ(common::sceneToJson(back), json);  // and writing it again changes nothing
}

TEST(SceneJson, RelativePathsAreRelativeToTheSceneFile) {
    common::Scene scene = common::parseScene(
        R"({"models": [{"file": "m.obj", "materials": {"x": {"diffuseTexture": "t/x.png"}}}]})", "test",
        "/scenes");
    EXPECT_EQ(scene.models[0].file, std::filesystem::path("/scenes/m.obj"));
    EXPECT_EQ(*scene.models[0].materials["x"].diffuseTexture, std::filesystem::path("/scenes/t/x.png"));
}

TEST(SceneJson, DefaultsForWhatAFileLeavesOut) {
    common::Scene scene = common::parseScene(R"({"models": [{"file": "m.obj"}]})", "test", "/");
    EXPECT_EQ(scene.camera, common::CameraDesc{});
    EXPECT_EQ(scene.models[0].transform, common::Transform{});
    EXPECT_TRUE(scene.lights.empty());
}

// The message must name the file and the key, on one line.
void expectRefused(const std::string& json, const std::string& expected) {
    try {
        common::parseScene(json, "bad.json", "/");
        ADD_FAILURE() << "accepted: " << json;
    } catch (const common::InputError& error) {
        std::string message = error.what();
        EXPECT_NE(message.find("bad.json: "), std::string::npos) << message;
        EXPECT_NE(message.find(expected), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(SceneJson, RefusesBadFiles) {
    expectRefused("{", "invalid JSON");
    expectRefused("[]", "scene: expected an object");
    expectRefused(R"({"models": []})", "models: expected a non-empty array");
    expectRefused(R"({"models": [{"file": 3}]})", "models[0].file: expected a non-empty string");
    expectRefused(R"({"models": [{"file": "m.obj", "scale": [1, 0, 1]}]})",
                  "models[0].scale: must not be zero");
    expectRefused(R"({"models": [{"file": "m.obj", "position": [1, 2]}]})",
                  "models[0].position: expected an array of 3");
    expectRefused(R"({"models": [{"file": "m.obj", "materials": {"a": {"roughness": 2}}}]})",
                  "models[0].materials.a.roughness: must be between 0 and 1");
    expectRefused(R"({"models": [{"file": "m.obj"}], "camera": {"near": 10, "far": 1}})", "camera.far");
    expectRefused(R"({"models": [{"file": "m.obj"}], "camera": {"fov": 180}})", "camera.fov");
    expectRefused(R"({"models": [{"file": "m.obj"}], "lights": [{"type": "spot"}]})", "lights[0].type");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "directional", "direction": [0, 0, 0]}]})",
        "lights[0].direction: must not be zero");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "point", "position": [0, 0, 0], "intensity": -1}]})",
        "lights[0].intensity");
    expectRefused(R"({"models": [{"file": "m.obj"}], "ambient": {"colour": [1, 1, 1]}})",
                  "unknown key 'colour'");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "point", "position": [0, 0, 0], "marker": 1}]})",
        "lights[0].marker: must be between 0 and 0");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "directional", "direction": [0, -1, 0], "marker": 0}]})",
        "lights[0].marker: only a point light has a marker");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "point", "position": [0, 0, 0], "range": 0}]})",
        "lights[0].range: must be greater than 0");
    expectRefused(
        R"({"models": [{"file": "m.obj"}], "lights": [{"type": "directional", "direction": [0, -1, 0], "range": 2}]})",
        "lights[0].range: only a point light has a range");
    expectRefused(R"({"models": [{"file": "m.obj"}], "camera": {"position": [0, 0, 1e999]}})",
                  "number overflow");
}

}  // namespace
