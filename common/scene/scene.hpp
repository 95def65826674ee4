// What a scene holds, read from a JSON scene file (or made for a single OBJ by --model):
// models with transforms and material overrides, a camera, lights and ambient light. Nothing
// about how it is drawn. The book builds the same content in code (its Scene, Entity, Camera,
// Projection and light classes, chapters 7-15); our scenes are files so readers can bring theirs.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/options.hpp"
#include "common/model/load_model.hpp"
#include "common/model/model.hpp"

namespace common {

struct Transform {
    glm::vec3 position{0.0f};
    glm::vec3 rotation{0.0f};  // Euler angles in degrees, applied about X, then Y, then Z
    glm::vec3 scale{1.0f};
    glm::mat4 matrix() const;
    bool operator==(const Transform&) const = default;
};

// Replaces what a model's MTL says about one of its materials, for one model instance.
struct MaterialOverride {
    std::optional<glm::vec4> diffuse;
    std::optional<float> roughness;
    std::optional<float> metallic;
    std::optional<std::filesystem::path> diffuseTexture;
    std::optional<std::filesystem::path> normalTexture;
    bool operator==(const MaterialOverride&) const = default;
};

struct ModelInstance {
    std::filesystem::path file;  // an OBJ; relative paths in the JSON are relative to the scene file
    Transform transform;
    std::map<std::string, MaterialOverride> materials;  // by MTL material name
    bool operator==(const ModelInstance&) const = default;
};

// The largest camera.far / camera.near a scene may ask for: what a depth buffer resolves.
inline constexpr double kMaxFarOverNear = 1e5;

struct CameraDesc {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;    // degrees; 0 looks along -Z, positive turns towards +X
    float pitch = 0.0f;  // degrees; positive looks up, within [-89, 89]
    float fov = 60.0f;   // vertical field of view, degrees
    float near = 0.1f;
    float far = 100.0f;
    bool operator==(const CameraDesc&) const = default;
};

struct Light {
    enum class Type { Directional, Point };
    Type type = Type::Directional;
    glm::vec3 position{0.0f};                // point lights
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional lights: the direction the light travels
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    int marker = -1;  // point lights: index of the model that marks the light and moves with it
    // Point lights, beyond the book: how far the light reaches, in scene units ("range"); its
    // falloff is windowed to reach zero there (pbr.glsl's rangeWindow). 0: no range, the book's
    // unbounded inverse-square falloff.
    float range = 0.0f;
    bool operator==(const Light&) const = default;
};

struct Scene {
    std::vector<ModelInstance> models;  // at least one
    CameraDesc camera;
    glm::vec3 ambientColor{1.0f};
    float ambientIntensity = 0.2f;
    std::vector<Light> lights;
    bool operator==(const Scene&) const = default;
};

// What a scene file may hold. Every model is a draw call recorded each frame, every light is shaded
// at every pixel unless culled (chapter-15 --light-culling tiled): 100,000 of each still renders
// (tests/reliability/hostile.cmake), and the
// lights buffer (32 bytes a light) stays far below the smallest maxStorageBufferRange (128 MiB).
inline constexpr size_t kMaxSceneModels = 100000;
inline constexpr size_t kMaxSceneLights = 100000;
// Draws in all: each placed model draws each of its meshes (a glTF model's primitives, once per
// node). A million, each a few hundred bytes of CPU work and memory a frame.
inline constexpr size_t kMaxSceneDraws = 1000000;

// Parses scene JSON. `origin` names the file in error messages; relative model paths are taken
// relative to `baseDir`. Throws InputError with one line naming the file and the offending key.
Scene parseScene(const std::string& json, const std::string& origin, const std::filesystem::path& baseDir);
Scene loadSceneFile(const std::filesystem::path& path);
// The JSON text of a scene (model paths written as stored).
std::string sceneToJson(const Scene& scene);

// A scene with one model and a camera that frames the model's bounds, plus the book's light
// set-up (ambient 0.2, a directional light straight down).
Scene sceneForModel(const std::filesystem::path& obj, glm::vec3 boundsMin, glm::vec3 boundsMax);

// The book's chapter-15 scene (lwjglgamedev/vulkanbook, booksamples/chapter-15: Main.java): its
// Sponza.gltf, found from `path` (the book's clone, or the .gltf itself), the book's camera and
// lights, and the point light's marker cube (the default scene's cube.gltf, next to the
// executable).
Scene bookScene(const std::filesystem::path& path);

// The scene the command line asks for: --model, --scene, --book-scene, or the default scene
// generated at build time next to the executable (scenes/default/scene.json).
// --model reads the OBJ into `models` for its bounds.
Scene sceneFromOptions(const Options& options, ModelCache& models);

}  // namespace common
