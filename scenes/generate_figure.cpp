// generate_figure KIND OUT.gltf [N]: one of the skinned figures of scenes/figures.hpp, for the
// tests and for readers who want a figure to try chapter-17 on.
//   arm, tube, walker      chapter-17's figures (the default scene holds the walker and the arm)
//   strip N                N vertices (any N from 1) on two joints, bending: counts that are not
//                          a multiple of the skinning shader's 32
//   chain N                a tube on a chain of N joints (N from 2 to 4096), curling
//   fourth                 the arm with its lower half on the fourth joint slot, weight exactly 1
//   scaled                 the arm with its elbow scaled (1, 2, 0.5): normals need the inverse transpose
//   hemispheres            the arm's elbow keyed at q and then -q' (q' near q): slerp goes the short way
//   one-key                the arm with a clip of one key frame
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "figures.hpp"

namespace {

using namespace figures;

gltf::File strip(long n) {
    SkinnedMesh mesh;
    // Its zigzag 0.1 high, lower for long strips (at most 100 units of height in all), so that
    // millions of vertices still make a frame the frame-cost bound admits.
    const float step = 2.0f / float(n), height = std::min(0.1f, 100.0f / float(n));
    for (long i = 0; i < n; ++i) {
        float x = float(i) * step;
        glm::u16vec4 j;
        glm::vec4 w;
        blend(x, 0.8f, 1.2f, 0, 1, j, w);
        mesh.vertex({x, (i % 2) ? height : 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {x * 0.5f, float(i % 2)}, j, w);
    }
    if (n < 3) {
        mesh.indices = {0, uint32_t(std::min(1L, n - 1)), uint32_t(std::min(2L, n - 1))};
    } else {
        for (long i = 0; i + 2 < n; ++i)
            mesh.indices.insert(mesh.indices.end(),
                                {uint32_t(i), uint32_t(i + 1 + i % 2), uint32_t(i + 2 - i % 2)});
    }
    std::vector<Joint> joints{{}, {.parent = 0, .translation = {1.0f, 0.0f, 0.0f}}};
    Track bend{.joint = 1,
               .path = "rotation",
               .times = {0.0f, 1.0f},
               .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 90)})};
    return write(mesh, joints, {bend}, {0.8f, 0.8f, 0.8f, 1.0f}, "bend");
}

gltf::File chain(int n) {
    SkinnedMesh mesh;
    const float length = 4.0f, segment = length / float(n);
    mesh.tube(0.0f, length, 0.1f, 2 * n, 12, [&](float x, glm::u16vec4& j, glm::vec4& w) {
        float position = x / segment;  // joint k starts at k * segment
        int k = std::min(int(position), n - 1);
        float t = position - float(k);
        int next = std::min(k + 1, n - 1);
        j = {uint16_t(k), uint16_t(next), 0, 0};
        w = {1.0f - 0.5f * t, 0.5f * t, 0.0f, 0.0f};
    });
    std::vector<Joint> joints(static_cast<size_t>(n));
    std::vector<Track> tracks;
    for (int k = 1; k < n; ++k) {
        joints[size_t(k)] = {.parent = k - 1, .translation = {segment, 0.0f, 0.0f}};
        float degrees = 360.0f / float(n);
        tracks.push_back({.joint = k,
                          .path = "rotation",
                          .times = {0.0f, 1.0f, 2.0f},
                          .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, degrees),
                                           axisAngle({0, 0, 1}, 0)})});
    }
    return write(mesh, joints, tracks, {0.6f, 0.8f, 0.6f, 1.0f}, "curl");
}

gltf::File armVariant(const std::string& kind) {
    SkinnedMesh mesh;
    const bool fourth = kind == "fourth";
    mesh.tube(0.0f, 2.0f, 0.15f, 40, 24, [&](float x, glm::u16vec4& j, glm::vec4& w) {
        if (fourth) {
            j = x < 1.0f ? glm::u16vec4(0, 0, 0, 0) : glm::u16vec4(0, 0, 0, 1);
            w = x < 1.0f ? glm::vec4(1, 0, 0, 0) : glm::vec4(0, 0, 0, 1);
        } else {
            blend(x, 0.8f, 1.2f, 0, 1, j, w);
        }
    });
    std::vector<Joint> joints{{}, {.parent = 0, .translation = {1.0f, 0.0f, 0.0f}}};
    if (kind == "scaled") joints[1].scale = {1.0f, 2.0f, 0.5f};
    Track bend{.joint = 1,
               .path = "rotation",
               .times = {0.0f, 1.0f, 2.0f},
               .values = quats({axisAngle({0, 0, 1}, 0), axisAngle({0, 0, 1}, 60), axisAngle({0, 0, 1}, 0)})};
    if (kind == "hemispheres")  // 10 degrees, then 20 degrees written as -q: the same rotation
        bend = {.joint = 1,
                .path = "rotation",
                .times = {0.0f, 1.0f},
                .values = quats({axisAngle({0, 0, 1}, 10), -axisAngle({0, 0, 1}, 20)})};
    if (kind == "one-key")
        bend = {.joint = 1, .path = "rotation", .times = {0.5f}, .values = quats({axisAngle({0, 0, 1}, 45)})};
    if (kind == "scaled")  // the scale stays; the elbow bends
        joints[1].scale = {1.0f, 2.0f, 0.5f};
    return write(mesh, joints, {bend}, {0.85f, 0.55f, 0.35f, 1.0f}, kind);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: generate_figure KIND OUT.gltf [N]\n");
        return 2;
    }
    const std::string kind = argv[1];
    const long n = argc > 3 ? std::strtol(argv[3], nullptr, 10) : 0;
    try {
        gltf::File file;
        if (kind == "arm")
            file = arm();
        else if (kind == "tube")
            file = twistingTube();
        else if (kind == "walker")
            file = walker();
        else if (kind == "strip" && n >= 1 && n <= (1L << 22))
            file = strip(n);
        else if (kind == "chain" && n >= 2 && n <= 4096)
            file = chain(int(n));
        else if (kind == "fourth" || kind == "scaled" || kind == "hemispheres" || kind == "one-key")
            file = armVariant(kind);
        else {
            std::fprintf(stderr, "generate_figure: unknown figure '%s' (or N out of range)\n", kind.c_str());
            return 2;
        }
        file.writeGltf(argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "generate_figure: %s\n", e.what());
        return 1;
    }
    return 0;
}
