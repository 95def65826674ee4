// Unit tests of skins and animations: the glTF loader's rig (common/model/gltf_model.cpp) and the
// posing of it (common/model/animation.cpp), as the glTF 2.0 specification defines them
// (3.7.3 "Skins", 3.11 "Animations", Appendix C "Interpolation"), on figures written here with
// scenes/figures.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <glm/gtc/quaternion.hpp>

#include "../../scenes/figures.hpp"
#include "common/model/animation.hpp"
#include "common/model/load_model.hpp"
#include "common/model/model.hpp"

namespace {

namespace fs = std::filesystem;
using figures::axisAngle;
using figures::quats;

fs::path tempDir() {
    fs::path dir = fs::temp_directory_path() / "vkbook-animation-test";
    fs::create_directories(dir);
    return dir;
}

// A two-joint arm (the second joint at x = 1) whose elbow follows `track` (joint 1's).
common::ModelData arm(const figures::Track& track, const std::string& name) {
    figures::SkinnedMesh mesh;
    mesh.tube(0.0f, 2.0f, 0.1f, 8, 4,
              [](float x, glm::u16vec4& j, glm::vec4& w) { figures::blend(x, 0.8f, 1.2f, 0, 1, j, w); });
    std::vector<figures::Joint> joints{{}, {.parent = 0, .translation = {1, 0, 0}}};
    figures::write(mesh, joints, {track}, {1, 1, 1, 1}, "clip").writeGltf(tempDir() / name);
    return common::loadModel(tempDir() / name);
}

// The rotation angle (degrees, about z) of the elbow's world matrix at `seconds`.
double elbowDegrees(const common::ModelData& model, double seconds) {
    common::Pose pose;
    common::poseRig(model.rig, 0, seconds, pose);
    glm::dmat4 m = pose.joints[1];
    return glm::degrees(std::atan2(m[0][1], m[0][0]));
}

TEST(Animation, LinearRotationTakesTheShortWayBetweenOppositeHemispheres) {
    // 10 degrees, then 20 degrees written as -q (the same rotation, the other hemisphere): halfway
    // is 15 degrees; a lerp of the raw quaternions would pass near zero and turn the long way.
    figures::Track track{.joint = 1,
                         .path = "rotation",
                         .times = {0.0f, 1.0f},
                         .values = quats({axisAngle({0, 0, 1}, 10), -axisAngle({0, 0, 1}, 20)})};
    common::ModelData model = arm(track, "hemispheres.gltf");
    EXPECT_NEAR(elbowDegrees(model, 0.5), 15.0, 1e-4);
    EXPECT_NEAR(elbowDegrees(model, 0.25), 12.5, 1e-4);
}

TEST(Animation, StepHoldsEachKeyUntilTheNext) {
    figures::Track track{
        .joint = 1,
        .path = "rotation",
        .interpolation = "STEP",
        .times = {0.0f, 1.0f, 2.0f},
        .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 30), axisAngle({0, 0, 1}, 60)})};
    common::ModelData model = arm(track, "step.gltf");
    EXPECT_NEAR(elbowDegrees(model, 0.999), 0.0, 1e-6);
    EXPECT_NEAR(elbowDegrees(model, 1.0), 30.0, 1e-4);
    EXPECT_NEAR(elbowDegrees(model, 1.5), 30.0, 1e-4);
}

TEST(Animation, CubicSplineFollowsHermiteWithScaledTangents) {
    // Translation of the elbow along y: keys 0 and 1 at t = 0 and 2, out-tangent of the first 1,
    // in-tangent of the second 0. p(u) = (2u^3 - 3u^2 + 1) 0 + 2 (u^3 - 2u^2 + u) 1 + (-2u^3 + 3u^2) 1.
    figures::Track track{.joint = 1,
                         .path = "translation",
                         .interpolation = "CUBICSPLINE",
                         .times = {0.0f, 2.0f},
                         .values = {0, 0, 0, 0, 0, 0, 0, 1, 0, /* key 1 */ 0, 0, 0, 0, 1, 0, 0, 0, 0}};
    common::ModelData model = arm(track, "cubic.gltf");
    common::Pose pose;
    for (double u : {0.25, 0.5, 0.75}) {
        common::poseRig(model.rig, 0, 2.0 * u, pose);
        double expected = 2.0 * (u * u * u - 2 * u * u + u) + (-2 * u * u * u + 3 * u * u);
        EXPECT_NEAR(pose.world[model.rig.joints[1].node][3][1], expected, 1e-6) << "u = " << u;
    }
}

TEST(Animation, OneKeyFrameHoldsItsValue) {
    figures::Track track{
        .joint = 1, .path = "rotation", .times = {0.5f}, .values = quats({axisAngle({0, 0, 1}, 45)})};
    common::ModelData model = arm(track, "one_key.gltf");
    for (double t : {0.0, 0.25, 0.5, 1e6}) EXPECT_NEAR(elbowDegrees(model, t), 45.0, 1e-4) << t;
}

TEST(Animation, LoopsWithoutLosingTimeAfterElevenDays) {
    figures::Track track{
        .joint = 1,
        .path = "rotation",
        .times = {0.0f, 1.0f, 2.0f},
        .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 90), axisAngle({0, 0, 1}, 0)})};
    common::ModelData model = arm(track, "loop.gltf");
    ASSERT_EQ(model.rig.clips[0].duration, 2.0);
    EXPECT_DOUBLE_EQ(common::clipTime(model.rig.clips[0], 1e6 + 0.25), 0.25);
    EXPECT_NEAR(elbowDegrees(model, 1e6 + 0.5), elbowDegrees(model, 0.5), 1e-9);
    EXPECT_NEAR(elbowDegrees(model, 0.5), 45.0, 1e-4);
}

TEST(Animation, NormalsOfANonUniformlyScaledJointUseTheInverseTranspose) {
    figures::Track track{.joint = 1, .path = "scale", .times = {0.0f}, .values = {1.0f, 2.0f, 0.5f}};
    common::ModelData model = arm(track, "scaled.gltf");
    common::Pose pose;
    common::poseRig(model.rig, 0, 0.0, pose);
    // The elbow scaled (1, 2, 0.5) by the clip. A normal along (1, 1, 0)/sqrt 2 on its joint: the surface's
    // normal becomes (1, 1/2, 0) normalised, not the scaled vector (1, 2, 0).
    common::Vertex v{.position = {1.5f, 0, 0},
                     .normal = glm::normalize(glm::vec3(1, 1, 0)),
                     .tangent = {0, 0, 1},
                     .bitangent = {1, -1, 0}};
    common::VertexSkin skin;
    skin.joints[0] = 1;
    common::SkinnedVertex out = common::skinVertex(v, skin, pose.joints);
    glm::dvec3 expected = glm::normalize(glm::dvec3(1, 0.5, 0));
    EXPECT_NEAR(glm::length(out.normal - expected), 0.0, 1e-12);
}

TEST(Animation, WeightsWithinRoundingAreMadeToSumToOne) {
    figures::SkinnedMesh mesh;
    mesh.tube(0.0f, 2.0f, 0.1f, 2, 4, [](float, glm::u16vec4& j, glm::vec4& w) {
        j = {0, 1, 0, 0};
        w = {0.5f, 0.495f, 0.0f, 0.0f};
    });
    std::vector<figures::Joint> joints{{}, {.parent = 0, .translation = {1, 0, 0}}};
    figures::write(mesh, joints, {}, {1, 1, 1, 1}, "none").writeGltf(tempDir() / "rounded.gltf");
    common::ModelData model = common::loadModel(tempDir() / "rounded.gltf");
    ASSERT_FALSE(model.meshes[0].skin.empty());
    const glm::vec4 w = model.meshes[0].skin[0].weights;
    EXPECT_NEAR(double(w.x) + w.y + w.z + w.w, 1.0, 1e-7);
    EXPECT_NEAR(w.x / w.y, 0.5 / 0.495, 1e-6);
}

TEST(Animation, TheFourthSlotKeepsItsJoint) {
    figures::SkinnedMesh mesh;
    mesh.tube(0.0f, 2.0f, 0.1f, 2, 4, [](float, glm::u16vec4& j, glm::vec4& w) {
        j = {0, 0, 0, 1};
        w = {0, 0, 0, 1};
    });
    std::vector<figures::Joint> joints{{}, {.parent = 0, .translation = {1, 0, 0}}};
    figures::write(mesh, joints, {}, {1, 1, 1, 1}, "none").writeGltf(tempDir() / "fourth.gltf");
    common::ModelData model = common::loadModel(tempDir() / "fourth.gltf");
    EXPECT_EQ(model.meshes[0].skin[0].joints[3], 1);
    EXPECT_EQ(model.meshes[0].skin[0].weights, glm::vec4(0, 0, 0, 1));
}

TEST(Animation, PosedBoundsHoldEveryPosedVertex) {
    figures::Track track{.joint = 1,
                         .path = "rotation",
                         .times = {0.0f, 1.0f},
                         .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 170)})};
    common::ModelData model = arm(track, "bounds.gltf");
    const common::MeshData& mesh = model.meshes[0];
    common::SkinBounds bounds = common::skinBounds(mesh);
    common::Pose pose;
    for (double t : {0.0, 0.3, 0.7, 1.0}) {
        common::poseRig(model.rig, 0, t, pose);
        glm::vec3 lo, hi;
        common::posedBounds(bounds, pose.joints, lo, hi);
        for (size_t v = 0; v < mesh.vertices.size(); ++v) {
            glm::dvec3 p = common::skinVertex(mesh.vertices[v], mesh.skin[v], pose.joints).position;
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(double(lo[a]), p[a] + 1e-5);
                EXPECT_GE(double(hi[a]), p[a] - 1e-5);
            }
        }
    }
}

}  // namespace
