// Scene files: strict JSON reading (nlohmann-json) and writing.
#include "common/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/load_model.hpp"

namespace common {
namespace {

using nlohmann::json;

// A key as the JSON writes it, without the quotes: a "\n" in a key stays two characters, so every
// message is one line.
std::string escaped(const std::string& key) {
    std::string text = json(key).dump();
    return text.substr(1, text.size() - 2);
}

// Reads one JSON value with a path for messages ("models[2].transform.scale").
class Reader {
public:
    Reader(std::string origin) : origin_(std::move(origin)) {}

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw InputError(origin_ + ": " + where + ": " + what);
    }

    void onlyKeys(const json& object, const std::string& where,
                  std::initializer_list<const char*> allowed) const {
        if (!object.is_object()) fail(where, "expected an object");
        for (const auto& [key, value] : object.items()) {
            bool known = false;
            for (const char* name : allowed) known = known || key == name;
            if (!known) fail(where, "unknown key '" + escaped(key) + "'");
        }
    }

    float number(const json& value, const std::string& where, float min, float max) const {
        if (!value.is_number()) fail(where, "expected a number");
        double d = value.get<double>();
        if (!std::isfinite(d)) fail(where, "expected a finite number");
        if (d < min || d > max)
            fail(where, "must be between " + format(min) + " and " + format(max) + ", got " + format(d));
        return static_cast<float>(d);
    }

    template <int N>
    glm::vec<N, float> vector(const json& value, const std::string& where, float min, float max) const {
        if (!value.is_array() || value.size() != N)
            fail(where, "expected an array of " + std::to_string(N) + " numbers");
        glm::vec<N, float> v;
        for (int i = 0; i < N; ++i)
            v[i] = number(value[size_t(i)], where + "[" + std::to_string(i) + "]", min, max);
        return v;
    }

    std::string string(const json& value, const std::string& where) const {
        if (!value.is_string() || value.get<std::string>().empty())
            fail(where, "expected a non-empty string");
        const std::string& text = value.get_ref<const std::string&>();
        // File names and types: a line break in one would break the one-line messages that name it.
        if (hasControlCharacter(text))
            fail(where, "must not contain control characters (NUL, a line break, ...)");
        return text;
    }

private:
    static std::string format(double d) {
        std::ostringstream out;
        out << d;
        return out.str();
    }
    std::string origin_;
};

constexpr float kHuge = 1e30f;  // finite, but nothing a scene can sensibly exceed
// Places and distances: those of a model's vertices (common/model/model.hpp), so that their squares,
// and sums of them, stay finite in 32-bit floats.
constexpr float kFar = kMaxModelCoordinate;
// A light's radiance is colour x intensity. Each may be large, but the shading multiplies their
// product by 1/d^2 (d down to 1 cm), by the BRDF's peak and sums it over lights: beyond 1e20 that
// can exceed the largest 32-bit float (3.4e38) and turn pixels infinite.
constexpr double kMaxRadiance = 1e20;

void checkRadiance(const Reader& r, const std::string& where, glm::vec3 color, float intensity) {
    double radiance = double(std::max({color.r, color.g, color.b})) * double(intensity);
    if (radiance > kMaxRadiance) {
        char text[64];
        std::snprintf(text, sizeof(text), "%g", radiance);
        r.fail(where, std::string("color x intensity is ") + text +
                          ", more than 1e20: the shading would overflow 32-bit floats");
    }
}

Transform readTransform(const Reader& r, const json& model, const std::string& where) {
    Transform t;
    if (model.contains("position"))
        t.position = r.vector<3>(model["position"], where + ".position", -kFar, kFar);
    if (model.contains("rotation"))
        t.rotation = r.vector<3>(model["rotation"], where + ".rotation", -360.0f, 360.0f);
    if (model.contains("scale")) {
        const json& s = model["scale"];
        t.scale = s.is_number() ? glm::vec3(r.number(s, where + ".scale", -kHuge, kHuge))
                                : r.vector<3>(s, where + ".scale", -kHuge, kHuge);
        if (t.scale.x == 0.0f || t.scale.y == 0.0f || t.scale.z == 0.0f)
            r.fail(where + ".scale", "must not be zero");
    }
    return t;
}

MaterialOverride readOverride(const Reader& r, const json& m, const std::string& where,
                              const std::filesystem::path& baseDir) {
    r.onlyKeys(m, where, {"diffuse", "roughness", "metallic", "diffuseTexture", "normalTexture"});
    MaterialOverride o;
    if (m.contains("diffuse")) o.diffuse = r.vector<4>(m["diffuse"], where + ".diffuse", 0.0f, 1.0f);
    if (m.contains("roughness")) o.roughness = r.number(m["roughness"], where + ".roughness", 0.0f, 1.0f);
    if (m.contains("metallic")) o.metallic = r.number(m["metallic"], where + ".metallic", 0.0f, 1.0f);
    if (m.contains("diffuseTexture"))
        o.diffuseTexture = baseDir / r.string(m["diffuseTexture"], where + ".diffuseTexture");
    if (m.contains("normalTexture"))
        o.normalTexture = baseDir / r.string(m["normalTexture"], where + ".normalTexture");
    return o;
}

json vec(const glm::vec3& v) {
    return json::array({v.x, v.y, v.z});
}
json vec(const glm::vec4& v) {
    return json::array({v.x, v.y, v.z, v.w});
}

}  // namespace

glm::mat4 Transform::matrix() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(rotation.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotation.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotation.x), glm::vec3(1, 0, 0));
    return glm::scale(m, scale);
}

Scene parseScene(const std::string& text, const std::string& origin, const std::filesystem::path& baseDir) {
    // nlohmann-json reads UTF-8 (and skips its byte order mark); UTF-16 would be a syntax error at
    // column 1.
    if (text.starts_with("\xff\xfe") || text.starts_with("\xfe\xff"))
        throw InputError(origin + ": UTF-16 text; save it as UTF-8");
    json root;
    try {
        root = json::parse(text);
    } catch (const json::exception& error) {  // syntax errors, and numbers out of double's range
        std::string what = error.what();
        size_t at = what.find("] ");  // drop the "[json.exception.parse_error.101] " prefix
        throw InputError(origin +
                         ": invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
    }
    Reader r(origin);
    r.onlyKeys(root, "scene", {"models", "camera", "ambient", "lights"});
    Scene scene;

    if (!root.contains("models") || !root["models"].is_array() || root["models"].empty())
        r.fail("models", "expected a non-empty array of models");
    if (root["models"].size() > kMaxSceneModels)
        r.fail("models",
               std::to_string(root["models"].size()) + " models, at most " + std::to_string(kMaxSceneModels));
    for (size_t i = 0; i < root["models"].size(); ++i) {
        const json& m = root["models"][i];
        std::string where = "models[" + std::to_string(i) + "]";
        r.onlyKeys(m, where, {"file", "position", "rotation", "scale", "materials"});
        if (!m.contains("file")) r.fail(where, "missing 'file'");
        ModelInstance model;
        model.file = baseDir / r.string(m["file"], where + ".file");
        model.transform = readTransform(r, m, where);
        if (m.contains("materials")) {
            if (!m["materials"].is_object())
                r.fail(where + ".materials", "expected an object keyed by material name");
            for (const auto& [name, value] : m["materials"].items())
                model.materials[name] =
                    readOverride(r, value, where + ".materials." + escaped(name), baseDir);
        }
        scene.models.push_back(std::move(model));
    }

    if (root.contains("camera")) {
        const json& c = root["camera"];
        r.onlyKeys(c, "camera", {"position", "yaw", "pitch", "fov", "near", "far"});
        CameraDesc& cam = scene.camera;
        if (c.contains("position")) cam.position = r.vector<3>(c["position"], "camera.position", -kFar, kFar);
        if (c.contains("yaw")) cam.yaw = r.number(c["yaw"], "camera.yaw", -360.0f, 360.0f);
        if (c.contains("pitch")) cam.pitch = r.number(c["pitch"], "camera.pitch", -89.0f, 89.0f);
        if (c.contains("fov")) cam.fov = r.number(c["fov"], "camera.fov", 1.0f, 179.0f);
        if (c.contains("near")) cam.near = r.number(c["near"], "camera.near", 1e-6f, kFar);
        if (c.contains("far")) cam.far = r.number(c["far"], "camera.far", 1e-6f, kFar);
        if (!(cam.far > cam.near)) r.fail("camera.far", "must be greater than camera.near");
        // The depth buffer resolves view distances up to far / near = 1e5 (at 1e5 the farthest
        // half of the view still has about 170 steps of a 24-bit depth; past 1.7e7 everything
        // beyond some distance rounds to depth 1 and is not drawn at all).
        if (double(cam.far) > kMaxFarOverNear * double(cam.near) * (1.0 + 1e-6)) {  // 1e5 as floats round it
            char ratio[64];
            std::snprintf(ratio, sizeof(ratio), "%g", double(cam.far) / double(cam.near));
            r.fail("camera.far",
                   std::string("far / near is ") + ratio +
                       ", more than 1e5: the depth buffer cannot tell distances that far apart");
        }
    }

    if (root.contains("ambient")) {
        const json& a = root["ambient"];
        r.onlyKeys(a, "ambient", {"color", "intensity"});
        if (a.contains("color")) scene.ambientColor = r.vector<3>(a["color"], "ambient.color", 0.0f, kHuge);
        if (a.contains("intensity"))
            scene.ambientIntensity = r.number(a["intensity"], "ambient.intensity", 0.0f, kHuge);
        checkRadiance(r, "ambient", scene.ambientColor, scene.ambientIntensity);
    }

    if (root.contains("lights")) {
        if (!root["lights"].is_array()) r.fail("lights", "expected an array");
        if (root["lights"].size() > kMaxSceneLights)
            r.fail("lights", std::to_string(root["lights"].size()) + " lights, at most " +
                                 std::to_string(kMaxSceneLights));
        for (size_t i = 0; i < root["lights"].size(); ++i) {
            const json& l = root["lights"][i];
            std::string where = "lights[" + std::to_string(i) + "]";
            r.onlyKeys(l, where, {"type", "position", "direction", "color", "intensity", "marker", "range"});
            Light light;
            std::string type = l.contains("type") ? r.string(l["type"], where + ".type") : "";
            if (type == "directional") {
                light.type = Light::Type::Directional;
                if (!l.contains("direction")) r.fail(where, "a directional light needs 'direction'");
                // [0, -1e30, 0] is a direction, but its length in 32-bit floats is infinite (and
                // every later normalisation would make it zero): one whose largest component
                // passes 1e15 is scaled, in double, to a largest component of 1 (the same
                // direction; smaller ones are kept as written, so a scene file reads back the same).
                glm::dvec3 direction(r.vector<3>(l["direction"], where + ".direction", -kHuge, kHuge));
                double largest =
                    glm::max(glm::max(std::abs(direction.x), std::abs(direction.y)), std::abs(direction.z));
                if (largest > 1e15) direction /= largest;
                if (!(glm::length(direction) >= 1e-6))
                    r.fail(where + ".direction", "must not be zero (its length is below 1e-6)");
                light.direction = glm::vec3(direction);
                if (l.contains("position"))
                    r.fail(where + ".position", "a directional light has no position");
            } else if (type == "point") {
                light.type = Light::Type::Point;
                if (!l.contains("position")) r.fail(where, "a point light needs 'position'");
                light.position = r.vector<3>(l["position"], where + ".position", -kFar, kFar);
                if (l.contains("direction")) r.fail(where + ".direction", "a point light has no direction");
            } else {
                r.fail(where + ".type", "expected \"directional\" or \"point\"");
            }
            if (l.contains("color")) light.color = r.vector<3>(l["color"], where + ".color", 0.0f, kHuge);
            if (l.contains("intensity"))
                light.intensity = r.number(l["intensity"], where + ".intensity", 0.0f, kHuge);
            checkRadiance(r, where, light.color, light.intensity);
            if (l.contains("range")) {
                if (light.type != Light::Type::Point)
                    r.fail(where + ".range", "only a point light has a range");
                light.range = r.number(l["range"], where + ".range", 0.0f, kFar);
                if (!(light.range > 0.0f)) r.fail(where + ".range", "must be greater than 0");
            }
            if (l.contains("marker")) {
                if (light.type != Light::Type::Point)
                    r.fail(where + ".marker", "only a point light has a marker");
                float index = r.number(l["marker"], where + ".marker", 0.0f, float(scene.models.size() - 1));
                if (index != std::floor(index)) r.fail(where + ".marker", "expected the index of a model");
                light.marker = int(index);
            }
            scene.lights.push_back(light);
        }
    }
    return scene;
}

Scene loadSceneFile(const std::filesystem::path& path) {
    return parseScene(readInputFile(path), utf8(path), path.parent_path());
}

std::string sceneToJson(const Scene& scene) {
    json root;
    root["models"] = json::array();
    for (const ModelInstance& m : scene.models) {
        json model{{"file", utf8(m.file)},
                   {"position", vec(m.transform.position)},
                   {"rotation", vec(m.transform.rotation)},
                   {"scale", vec(m.transform.scale)}};
        for (const auto& [name, o] : m.materials) {
            json over = json::object();
            if (o.diffuse) over["diffuse"] = vec(*o.diffuse);
            if (o.roughness) over["roughness"] = *o.roughness;
            if (o.metallic) over["metallic"] = *o.metallic;
            if (o.diffuseTexture) over["diffuseTexture"] = o.diffuseTexture->string();
            if (o.normalTexture) over["normalTexture"] = o.normalTexture->string();
            model["materials"][name] = over;
        }
        root["models"].push_back(model);
    }
    const CameraDesc& c = scene.camera;
    root["camera"] = {{"position", vec(c.position)},
                      {"yaw", c.yaw},
                      {"pitch", c.pitch},
                      {"fov", c.fov},
                      {"near", c.near},
                      {"far", c.far}};
    root["ambient"] = {{"color", vec(scene.ambientColor)}, {"intensity", scene.ambientIntensity}};
    root["lights"] = json::array();
    for (const Light& l : scene.lights) {
        json light{{"color", vec(l.color)}, {"intensity", l.intensity}};
        if (l.type == Light::Type::Directional) {
            light["type"] = "directional";
            light["direction"] = vec(l.direction);
        } else {
            light["type"] = "point";
            light["position"] = vec(l.position);
            if (l.marker >= 0) light["marker"] = l.marker;
            if (l.range > 0.0f) light["range"] = l.range;
        }
        root["lights"].push_back(light);
    }
    return root.dump(2) + "\n";
}

Scene sceneForModel(const std::filesystem::path& obj, glm::vec3 boundsMin, glm::vec3 boundsMax) {
    Scene scene;
    scene.models.push_back(ModelInstance{.file = obj});
    // Frame the bounding sphere: back off along +Z until it fits the vertical field of view,
    // looking slightly down on it.
    glm::vec3 center = (boundsMin + boundsMax) * 0.5f;
    float radius = std::max(glm::length(boundsMax - boundsMin) * 0.5f, 1e-3f);
    CameraDesc& cam = scene.camera;
    cam.fov = 60.0f;
    cam.pitch = -15.0f;
    float distance = radius / std::sin(glm::radians(cam.fov * 0.5f));
    glm::vec3 back(0.0f, -std::sin(glm::radians(cam.pitch)), std::cos(glm::radians(cam.pitch)));
    cam.position = center + back * distance;
    cam.near = std::max(distance - radius, distance * 1e-3f) * 0.5f;
    cam.far = (distance + radius) * 2.0f;
    scene.lights.push_back(Light{.type = Light::Type::Directional, .direction = {0.0f, -1.0f, 0.0f}});
    return scene;
}

//> book-scene
Scene bookScene(const std::filesystem::path& path) {
    std::filesystem::path gltf = path;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        gltf = path / "booksamples" / "chapter-15" / "resources" / "models" / "sponza" / "Sponza.gltf";
    if (!std::filesystem::is_regular_file(gltf, ec))
        throw InputError(utf8(gltf) +
                         ": no such file (--book-scene takes the book's clone or its Sponza.gltf)");
    Scene scene;
    scene.models.push_back(ModelInstance{.file = gltf});
    // Main.java: camera at (0, 5, 0), rotated 20 degrees about x and 90 about y in the book's
    // convention (view = rotateX * rotateY * translate): it looks along +x, tilted down. In ours,
    // yaw 90 looks along +x and pitch -20 down. Projection: fov 60, zNear 1, zFar 50.
    scene.camera = {.position = {0.0f, 5.0f, 0.0f},
                    .yaw = 90.0f,
                    .pitch = -20.0f,
                    .fov = 60.0f,
                    .near = 1.0f,
                    .far = 50.0f};
    scene.ambientColor = glm::vec3(1.0f);
    scene.ambientIntensity = 0.2f;
    scene.lights.push_back(Light{.type = Light::Type::Directional, .direction = {0.0f, -1.0f, 0.0f}});
    // The green point light, and a cube scaled 0.1 that marks it (ours is 2 units across).
    glm::vec3 point(5.0f, 3.4f, 1.2f);
    ModelInstance marker{.file = executableDir() / "scenes" / "default" / "cube.gltf"};
    marker.transform.position = point;
    marker.transform.scale = glm::vec3(0.1f);
    scene.models.push_back(marker);
    scene.lights.push_back(
        Light{.type = Light::Type::Point, .position = point, .color = {0.0f, 1.0f, 0.0f}, .marker = 1});
    return scene;
}
//< book-scene

Scene sceneFromOptions(const Options& options, ModelCache& models) {
    if (!options.bookScene.empty()) return bookScene(options.bookScene);
    if (!options.model.empty()) {
        const ModelData& model = loadModelCached(models, options.model);
        return sceneForModel(options.model, model.boundsMin, model.boundsMax);
    }
    if (!options.scene.empty()) return loadSceneFile(options.scene);
    std::filesystem::path defaultScene = executableDir() / "scenes" / "default" / "scene.json";
    std::error_code ec;
    if (!std::filesystem::exists(defaultScene, ec))
        throw Failure("the default scene '" + utf8(defaultScene) + "' is missing (is the build complete?)");
    return loadSceneFile(defaultScene);
}

}  // namespace common
