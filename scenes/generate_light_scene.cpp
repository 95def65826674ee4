// generate_light_scene DEFAULT_DIR N OUT.json [--no-range] [--range R] [--cluster]
//
// A many-light scene for chapter-15's light culling (beyond the book): the default courtyard
// (its models, from DEFAULT_DIR, referenced by relative path) at night -- dim ambient light, no
// sun -- lit by N coloured point lights scattered over the floor. The lights' ranges shrink as N
// grows so that the number of lights reaching a point of the floor stays about the same
// (kLightsPerPoint): N lights of range r cover N pi r^2 of the 30 x 30 floor, so
// r = sqrt(kLightsPerPoint x 900 / (pi N)). Each hangs at 0.3 r above the floor with intensity
// proportional to r^2, so the floor is about equally bright for every N.
//   --no-range  leave the ranges out (the book's unbounded falloff; chapter-15 --light-cutoff
//               then derives them);
//   --range R   every light's range R instead (tests: lights that each cover the whole screen);
//   --cluster   every light within 1 cm of one point 3 cm above the floor in front of the
//               camera, range 5 cm: N lights in one or a few 8x8-pixel tiles (a hard case for
//               the tile lists).
// Deterministic: positions and colours come from integer hashes.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/files.hpp"
#include "common/scene/scene.hpp"

namespace fs = std::filesystem;

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kFloorArea = 30.0f * 30.0f;
constexpr float kLightsPerPoint = 6.0f;

float hash01(uint32_t i, uint32_t seed) {
    uint32_t h = i * 0x8da6b343u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffffu) / float(0xffffff);
}

glm::vec3 hueToRgb(float hue) {
    glm::vec3 k =
        glm::abs(glm::fract(glm::vec3(hue) + glm::vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f);
    glm::vec3 rgb = glm::clamp(k - 1.0f, 0.0f, 1.0f);
    return glm::mix(glm::vec3(1.0f), rgb, 0.7f);  // saturation 0.7
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(
            stderr,
            "usage: generate_light_scene DEFAULT_DIR N OUT.json [--no-range] [--range R] [--cluster]\n");
        return 2;
    }
    fs::path defaultDir = argv[1];
    long n = std::strtol(argv[2], nullptr, 10);
    fs::path out = argv[3];
    bool ranges = true, cluster = false;
    float fixedRange = 0.0f;
    for (int i = 4; i < argc; ++i) {
        if (std::strcmp(argv[i], "--no-range") == 0)
            ranges = false;
        else if (std::strcmp(argv[i], "--range") == 0 && i + 1 < argc)
            fixedRange = std::strtof(argv[++i], nullptr);
        else if (std::strcmp(argv[i], "--cluster") == 0)
            cluster = true;
        else {
            std::fprintf(stderr, "generate_light_scene: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if (n < 1 || n > long(common::kMaxSceneLights)) {
        std::fprintf(stderr, "generate_light_scene: N must be 1..%zu\n", common::kMaxSceneLights);
        return 2;
    }
    try {
        fs::create_directories(out.parent_path().empty() ? fs::path(".") : out.parent_path());
        // The default scene's models, minus the marker cube of its point light; paths relative to
        // the new file, so the build folder can move.
        common::Scene scene = common::loadSceneFile(defaultDir / "scene.json");
        fs::path base = fs::weakly_canonical(out).parent_path();
        std::vector<common::ModelInstance> models;
        for (common::ModelInstance& model : scene.models) {
            if (model.file.filename() == "cube.obj") continue;
            model.file = fs::relative(fs::weakly_canonical(model.file), base);
            models.push_back(model);
        }
        scene.models = models;
        scene.ambientIntensity = 0.02f;
        scene.lights.clear();

        float range = cluster ? 0.05f : std::sqrt(kLightsPerPoint * kFloorArea / (kPi * float(n)));
        // Clustered: the lights' sum stays that of 64 lights.
        float intensity = 0.15f * range * range * (cluster ? 64.0f / float(n) : 1.0f);
        for (uint32_t i = 0; i < uint32_t(n); ++i) {
            common::Light light{.type = common::Light::Type::Point};
            if (cluster)
                light.position = glm::vec3(0.0f, 0.03f, 8.0f) +
                                 (glm::vec3(hash01(i, 1), hash01(i, 2), hash01(i, 3)) - 0.5f) * 0.02f;
            else
                light.position = {-14.5f + 29.0f * hash01(i, 1), 0.3f * range, -14.5f + 29.0f * hash01(i, 2)};
            light.color = hueToRgb(hash01(i, 4));
            light.intensity = cluster ? intensity * 10.0f : intensity;
            if (ranges) light.range = fixedRange > 0.0f ? fixedRange : range;
            scene.lights.push_back(light);
        }
        // The scene without its lights as the library writes it, then the lights one per line
        // with 6 significant digits: 65,536 lights take 7 MB instead of 21.
        std::vector<common::Light> lights = std::move(scene.lights);
        scene.lights.clear();
        std::string text = common::sceneToJson(scene);
        size_t empty = text.find("\"lights\": []");
        if (empty == std::string::npos) throw std::runtime_error("unexpected scene JSON");
        std::string list = "\"lights\": [\n";
        for (size_t i = 0; i < lights.size(); ++i) {
            const common::Light& l = lights[i];
            char line[320];
            int length = std::snprintf(
                line, sizeof line,
                "    {\"type\": \"point\", \"position\": [%.6g, %.6g, %.6g], \"color\": [%.4g, %.4g, %.4g], "
                "\"intensity\": %.6g",
                double(l.position.x), double(l.position.y), double(l.position.z), double(l.color.r),
                double(l.color.g), double(l.color.b), double(l.intensity));
            list.append(line, size_t(length));
            if (l.range > 0.0f) list += ", \"range\": " + std::to_string(l.range);
            list += i + 1 < lights.size() ? "},\n" : "}\n";
        }
        list += "  ]";
        text.replace(empty, std::strlen("\"lights\": []"), list);
        std::ofstream file(out, std::ios::binary);
        file << text;
        if (!file.flush()) throw std::runtime_error("cannot write " + common::utf8(out));
        std::printf("generate_light_scene: %ld lights of range %.3g in %s\n", n, double(range),
                    common::utf8(out).c_str());
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "generate_light_scene: %s\n", error.what());
        return 1;
    }
}
