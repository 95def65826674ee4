// Skinned, animated figures as glTF 2.0 (skins 3.7.3, animations 3.11), generated: chapter-17's
// default figures (a walking biped of boxes, a bending arm, a twisting tube) and the tests' hard
// cases (vertex counts that are not a multiple of the skinning shader's group, 256 joints, a
// weight of 1 on the fourth joint, a non-uniformly scaled joint, rotation keys on opposite
// hemispheres, a clip of one key frame). Written by generate_default_scene and generate_figure.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_writer.hpp"

namespace figures {

using gltf::json;

// A mesh being built: vertices with normals and uvs, each with its four joints and weights.
struct SkinnedMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::u16vec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<uint32_t> indices;

    uint32_t vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv, glm::u16vec4 j, glm::vec4 w) {
        positions.push_back(p);
        normals.push_back(n);
        uvs.push_back(uv);
        joints.push_back(j);
        weights.push_back(w);
        return uint32_t(positions.size() - 1);
    }

    // An axis-aligned box, centre c and half sizes h, every vertex on one joint.
    void box(glm::vec3 c, glm::vec3 h, uint16_t joint) {
        for (int axis = 0; axis < 3; ++axis)
            for (int side = -1; side <= 1; side += 2) {
                glm::vec3 n(0.0f);
                n[axis] = float(side);
                glm::vec3 u(0.0f), v(0.0f);
                u[(axis + 1) % 3] = 1.0f;
                v[(axis + 2) % 3] = 1.0f;
                if (side < 0) std::swap(u, v);  // counter-clockwise seen from outside
                uint32_t base = uint32_t(positions.size());
                for (int k = 0; k < 4; ++k) {
                    float a = (k == 1 || k == 2) ? 1.0f : -1.0f, b = k >= 2 ? 1.0f : -1.0f;
                    vertex(c + h * (n + a * u + b * v), n, {a * 0.5f + 0.5f, b * 0.5f + 0.5f},
                           {joint, 0, 0, 0}, {1, 0, 0, 0});
                }
                indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            }
    }

    // A tube along +x from x0 to x1, `rings` x `sides`, its weights from `weigh` (x -> joints, weights).
    template <typename Weigh>
    void tube(float x0, float x1, float radius, int rings, int sides, Weigh weigh) {
        uint32_t base = uint32_t(positions.size());
        for (int r = 0; r <= rings; ++r) {
            float x = x0 + (x1 - x0) * float(r) / float(rings);
            glm::u16vec4 j;
            glm::vec4 w;
            weigh(x, j, w);
            for (int s = 0; s <= sides; ++s) {
                float a = 6.2831853f * float(s) / float(sides);
                glm::vec3 n(0.0f, std::cos(a), std::sin(a));
                vertex(glm::vec3(x, 0.0f, 0.0f) + radius * n, n,
                       {float(s) / float(sides), float(r) / float(rings)}, j, w);
            }
        }
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < sides; ++s) {
                uint32_t a = base + uint32_t(r * (sides + 1) + s), b = a + uint32_t(sides + 1);
                indices.insert(indices.end(), {a, a + 1, b + 1, a, b + 1, b});
            }
    }
};

struct Joint {
    int parent = -1;
    glm::vec3 translation{0.0f};  // rest, relative to the parent
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
};

struct Track {
    int joint = 0;
    std::string path;  // "translation", "rotation", "scale"
    std::string interpolation = "LINEAR";
    std::vector<float> times;
    std::vector<float> values;  // 3 or 4 a key (x3 for CUBICSPLINE)
};

inline std::vector<float> quats(std::initializer_list<glm::quat> qs) {
    std::vector<float> out(4 * qs.size());
    size_t i = 0;
    for (const glm::quat& q : qs) {
        out[i++] = q.x;
        out[i++] = q.y;
        out[i++] = q.z;
        out[i++] = q.w;
    }
    return out;
}

inline glm::quat axisAngle(glm::vec3 axis, float degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// The file: one mesh skinned by the joints (their inverse bind matrices from the rest pose), one
// animation of the tracks, a material of `color`.
inline gltf::File write(const SkinnedMesh& mesh, const std::vector<Joint>& joints,
                        const std::vector<Track>& tracks, glm::vec4 color, const std::string& clipName) {
    gltf::File file;
    std::vector<glm::mat4> world(joints.size());
    std::vector<int> jointNodes;
    for (size_t j = 0; j < joints.size(); ++j) {
        const Joint& joint = joints[j];
        glm::mat4 local = glm::translate(glm::mat4(1.0f), joint.translation) *
                          glm::mat4_cast(joint.rotation) * glm::scale(glm::mat4(1.0f), joint.scale);
        world[j] = joint.parent >= 0 ? world[size_t(joint.parent)] * local : local;
        json node = {{"name", "joint " + std::to_string(j)},
                     {"translation", {joint.translation.x, joint.translation.y, joint.translation.z}},
                     {"rotation", {joint.rotation.x, joint.rotation.y, joint.rotation.z, joint.rotation.w}},
                     {"scale", {joint.scale.x, joint.scale.y, joint.scale.z}}};
        jointNodes.push_back(file.node(node));
    }
    for (size_t j = 0; j < joints.size(); ++j)
        if (joints[j].parent >= 0)
            file.root["nodes"][size_t(joints[j].parent)]["children"].push_back(jointNodes[j]);
    std::vector<glm::mat4> inverseBind;
    for (const glm::mat4& m : world) inverseBind.push_back(glm::inverse(m));

    json attributes = {{"POSITION", file.positions(mesh.positions)},
                       {"NORMAL", file.values(mesh.normals, gltf::kFloat, "VEC3")},
                       {"TEXCOORD_0", file.values(mesh.uvs, gltf::kFloat, "VEC2")},
                       {"JOINTS_0", file.values(mesh.joints, gltf::kUnsignedShort, "VEC4")},
                       {"WEIGHTS_0", file.values(mesh.weights, gltf::kFloat, "VEC4")}};
    int material = file.material({{"pbrMetallicRoughness",
                                   {{"baseColorFactor", {color.r, color.g, color.b, color.a}},
                                    {"metallicFactor", 0.0},
                                    {"roughnessFactor", 0.6}}}});
    int meshIndex =
        file.mesh(json::array({{{"attributes", attributes},
                                {"indices", file.values(mesh.indices, gltf::kUnsignedInt, "SCALAR")},
                                {"material", material}}}));
    int skin = file.add("skins", {{"joints", jointNodes},
                                  {"inverseBindMatrices", file.values(inverseBind, gltf::kFloat, "MAT4")}});
    int skinned = file.node({{"name", "figure"}, {"mesh", meshIndex}, {"skin", skin}});
    std::vector<int> roots{skinned};
    for (size_t j = 0; j < joints.size(); ++j)
        if (joints[j].parent < 0) roots.push_back(jointNodes[j]);
    file.scene(roots);

    if (!tracks.empty()) {
        json channels = json::array(), samplers = json::array();
        for (const Track& track : tracks) {
            int input = file.values(track.times, gltf::kFloat, "SCALAR");
            float lo = track.times.front(), hi = track.times.back();
            file.root["accessors"][size_t(input)]["min"] = {lo};
            file.root["accessors"][size_t(input)]["max"] = {hi};
            int output = file.values(track.values, gltf::kFloat, track.path == "rotation" ? "VEC4" : "VEC3");
            samplers.push_back(
                {{"input", input}, {"output", output}, {"interpolation", track.interpolation}});
            channels.push_back(
                {{"sampler", samplers.size() - 1},
                 {"target", {{"node", jointNodes[size_t(track.joint)]}, {"path", track.path}}}});
        }
        file.add("animations", {{"name", clipName}, {"channels", channels}, {"samplers", samplers}});
    }
    return file;
}

// A weight that moves from joint a to joint b across [x0, x1] (smoothstep).
inline void blend(float x, float x0, float x1, uint16_t a, uint16_t b, glm::u16vec4& j, glm::vec4& w) {
    float t = glm::clamp((x - x0) / (x1 - x0), 0.0f, 1.0f);
    t = t * t * (3.0f - 2.0f * t);
    j = {a, b, 0, 0};
    w = {1.0f - t, t, 0.0f, 0.0f};
}

// An arm 2 long along +x: the upper half on the shoulder, the lower on the elbow at x = 1, the
// skin blended over [0.8, 1.2]; the elbow bends 0 -> 100 degrees -> 0 in 2 s, the shoulder
// swings +-20 degrees about y.
inline gltf::File arm() {
    SkinnedMesh mesh;
    mesh.tube(0.0f, 2.0f, 0.15f, 40, 24,
              [](float x, glm::u16vec4& j, glm::vec4& w) { blend(x, 0.8f, 1.2f, 0, 1, j, w); });
    std::vector<Joint> joints{{}, {.parent = 0, .translation = {1.0f, 0.0f, 0.0f}}};
    std::vector<Track> tracks{
        {.joint = 1,
         .path = "rotation",
         .times = {0.0f, 1.0f, 2.0f},
         .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 100), axisAngle({0, 0, 1}, 0)})},
        {.joint = 0,
         .path = "rotation",
         .times = {0.0f, 0.5f, 1.5f, 2.0f},
         .values = quats({axisAngle({0, 1, 0}, 0), axisAngle({0, 1, 0}, 20), axisAngle({0, 1, 0}, -20),
                          axisAngle({0, 1, 0}, 0)})}};
    return write(mesh, joints, tracks, {0.85f, 0.55f, 0.35f, 1.0f}, "bend");
}

// The candy wrapper: a tube 2 long, its halves on two joints, the second twisted about the
// tube's axis 0 -> 180 degrees -> 0 (keys every 45 degrees, so every pair of keys has one way
// round), blended over the middle.
inline gltf::File twistingTube() {
    SkinnedMesh mesh;
    mesh.tube(0.0f, 2.0f, 0.25f, 64, 32,
              [](float x, glm::u16vec4& j, glm::vec4& w) { blend(x, 0.5f, 1.5f, 0, 1, j, w); });
    std::vector<Joint> joints{{}, {.parent = 0, .translation = {1.0f, 0.0f, 0.0f}}};
    Track twist{.joint = 1, .path = "rotation"};
    for (int k = 0; k <= 8; ++k) {
        float degrees = 45.0f * float(k <= 4 ? k : 8 - k);
        twist.times.push_back(0.25f * float(k));
        glm::quat q = axisAngle({1, 0, 0}, degrees);
        twist.values.insert(twist.values.end(), {q.x, q.y, q.z, q.w});
    }
    return write(mesh, joints, {twist}, {0.3f, 0.6f, 0.9f, 1.0f}, "twist");
}

// A biped of boxes 1.8 tall, every box on one joint: hips, spine, head, two legs (thigh, shin)
// and two arms; a walk in place of 1 s: legs and arms swing, the hips bob (CUBICSPLINE). With
// `travel`, it walks that far along -z in the clip's second instead of bobbing (LINEAR): a figure
// that crosses the shadow cascades.
inline gltf::File walker(float travel = 0.0f) {
    SkinnedMesh mesh;
    enum : uint16_t { Hips, Spine, Head, ThighL, ShinL, ThighR, ShinR, ArmL, ArmR };
    std::vector<Joint> joints(9);
    joints[Hips] = {.translation = {0.0f, 0.95f, 0.0f}};
    joints[Spine] = {.parent = Hips, .translation = {0.0f, 0.1f, 0.0f}};
    joints[Head] = {.parent = Spine, .translation = {0.0f, 0.6f, 0.0f}};
    joints[ThighL] = {.parent = Hips, .translation = {-0.12f, -0.05f, 0.0f}};
    joints[ShinL] = {.parent = ThighL, .translation = {0.0f, -0.45f, 0.0f}};
    joints[ThighR] = {.parent = Hips, .translation = {0.12f, -0.05f, 0.0f}};
    joints[ShinR] = {.parent = ThighR, .translation = {0.0f, -0.45f, 0.0f}};
    joints[ArmL] = {.parent = Spine, .translation = {-0.28f, 0.55f, 0.0f}};
    joints[ArmR] = {.parent = Spine, .translation = {0.28f, 0.55f, 0.0f}};
    // Boxes in the model's space at rest (the joints' world positions above).
    mesh.box({0.0f, 0.95f, 0.0f}, {0.2f, 0.1f, 0.12f}, Hips);
    mesh.box({0.0f, 1.35f, 0.0f}, {0.22f, 0.3f, 0.13f}, Spine);
    mesh.box({0.0f, 1.8f, 0.0f}, {0.11f, 0.13f, 0.12f}, Head);
    for (float side : {-1.0f, 1.0f}) {
        uint16_t thigh = side < 0 ? ThighL : ThighR, shin = side < 0 ? ShinL : ShinR,
                 arm = side < 0 ? ArmL : ArmR;
        mesh.box({0.12f * side, 0.68f, 0.0f}, {0.08f, 0.22f, 0.08f}, thigh);
        mesh.box({0.12f * side, 0.23f, 0.02f}, {0.07f, 0.22f, 0.1f}, shin);
        mesh.box({0.31f * side, 1.33f, 0.0f}, {0.05f, 0.28f, 0.05f}, arm);
    }
    std::vector<Track> tracks;
    auto swing = [&](int joint, float amplitude, float phase) {
        Track t{.joint = joint, .path = "rotation"};
        for (int k = 0; k <= 8; ++k) {
            float time = float(k) / 8.0f;
            t.times.push_back(time);
            glm::quat q = axisAngle({1, 0, 0}, amplitude * std::sin(6.2831853f * (time + phase)));
            t.values.insert(t.values.end(), {q.x, q.y, q.z, q.w});
        }
        tracks.push_back(t);
    };
    swing(ThighL, 30.0f, 0.0f);
    swing(ThighR, 30.0f, 0.5f);
    swing(ArmL, 25.0f, 0.5f);
    swing(ArmR, 25.0f, 0.0f);
    // Knees bend only one way: a step between 0 and 40 degrees.
    for (int joint : {ShinL, ShinR}) {
        Track t{.joint = joint, .path = "rotation", .interpolation = "STEP"};
        t.times = {0.0f, 0.5f};
        float first = joint == ShinL ? 40.0f : 5.0f, second = joint == ShinL ? 5.0f : 40.0f;
        t.values = quats({axisAngle({1, 0, 0}, first), axisAngle({1, 0, 0}, second)});
        tracks.push_back(t);
    }
    if (travel > 0.0f) {
        tracks.push_back({.joint = Hips,
                          .path = "translation",
                          .times = {0.0f, 1.0f},
                          .values = {0.0f, 0.95f, 0.0f, 0.0f, 0.95f, -travel}});
        return write(mesh, joints, tracks, {0.75f, 0.75f, 0.8f, 1.0f}, "walk away");
    }
    // The hips bob twice a step: a cubic spline through 0.95 and 1.0 with flat tangents.
    Track bob{.joint = Hips, .path = "translation", .interpolation = "CUBICSPLINE"};
    for (int k = 0; k <= 4; ++k) {
        bob.times.push_back(0.25f * float(k));
        float y = k % 2 ? 1.0f : 0.95f;
        bob.values.insert(bob.values.end(), {0, 0, 0, 0, y, 0, 0, 0, 0});
    }
    tracks.push_back(bob);
    return write(mesh, joints, tracks, {0.75f, 0.75f, 0.8f, 1.0f}, "walk");
}

}  // namespace figures
