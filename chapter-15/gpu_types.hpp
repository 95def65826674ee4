// chapter-15: the structs C++ writes and the shaders read, the twins of
// shaders/include/gpu_types.glsl. The static_asserts pin the layout this side; the layout test
// (tests/chapters/layout_test.cpp) checks on the GPU that the shader reads every field where C++ put it.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

//> gpu-types
// Light in a scalar-layout storage buffer: 36 bytes, vec3 on 4-byte alignment.
struct ShaderLight {
    glm::vec3 position;  // a point light's position; a directional light's travel direction
    uint32_t directional;
    float intensity;
    glm::vec3 color;
    float range;  // a point light's reach, from the scene (0: unbounded, the book's falloff)
};
static_assert(sizeof(ShaderLight) == 36);
static_assert(offsetof(ShaderLight, directional) == 12 && offsetof(ShaderLight, intensity) == 16 &&
              offsetof(ShaderLight, color) == 20 && offsetof(ShaderLight, range) == 32);

// SceneInfo in a scalar-layout uniform buffer: 32 bytes.
struct ShaderSceneInfo {
    glm::vec3 cameraPosition;
    float ambientIntensity;
    glm::vec3 ambientColor;
    uint32_t lightCount;
};
static_assert(sizeof(ShaderSceneInfo) == 32);
static_assert(offsetof(ShaderSceneInfo, ambientIntensity) == 12 &&
              offsetof(ShaderSceneInfo, ambientColor) == 16 && offsetof(ShaderSceneInfo, lightCount) == 28);

// Material in a std430 storage buffer: 48 bytes.
inline constexpr uint32_t kMaterialNormalMap = 1u;      // MATERIAL_NORMAL_MAP
inline constexpr uint32_t kMaterialMetalRoughMap = 2u;  // MATERIAL_METAL_ROUGH_MAP
inline constexpr uint32_t kMaterialOcclusionMap = 4u;   // MATERIAL_OCCLUSION_MAP
inline constexpr uint32_t kMaterialDoubleSided = 8u;    // MATERIAL_DOUBLE_SIDED
inline constexpr uint32_t kMaterialBaseColorMap = 16u;  // MATERIAL_BASE_COLOR_MAP
inline constexpr uint32_t kMaterialNormalScale = 32u;   // MATERIAL_NORMAL_SCALE
struct ShaderMaterial {
    glm::vec4 diffuse;
    float roughness;
    float metallic;
    uint32_t flags;
    float alphaCutoff;
    float normalScale;
    float occlusionStrength;
    glm::vec2 padding;
};
static_assert(sizeof(ShaderMaterial) == 48);
static_assert(offsetof(ShaderMaterial, roughness) == 16 && offsetof(ShaderMaterial, metallic) == 20 &&
              offsetof(ShaderMaterial, flags) == 24 && offsetof(ShaderMaterial, alphaCutoff) == 28 &&
              offsetof(ShaderMaterial, normalScale) == 32 &&
              offsetof(ShaderMaterial, occlusionStrength) == 36);
//< gpu-types

// The scene pass's vertex-stage push constants: the model matrix and its inverse-transpose (a
// mat3 is three 16-byte columns, std430). The fragment stage's material index follows at byte 112.
struct DrawConstants {
    glm::mat4 model;
    glm::vec4 normalMatrix[3];
};
static_assert(sizeof(DrawConstants) == 112 && offsetof(DrawConstants, normalMatrix) == 64);
// Where the fragment stage's material index lies in the push constants: DRAW_MATERIAL_OFFSET in
// shaders/include/gpu_types.glsl.
inline constexpr uint32_t kDrawMaterialOffset = sizeof(DrawConstants);
static_assert(kDrawMaterialOffset == 112);

// The light pass's push constants: 112 bytes.
struct LightView {
    glm::mat4 clipToCameraRelative{1.0f};  // positions from depth, for a layout that stores none
    glm::vec4 boundsMin{0.0f};             // the scene's bounds, to show world positions as colours
    glm::vec4 boundsMax{1.0f};
    int view = 0;       // 0 final, 1 position, 2 albedo, 3 normal, 4 pbr, 5 depth
    float near = 0.1f;  // the projection's planes
    float far = 100.0f;
    int reversedZ = 0;  // the G-buffer layout's reversedZ
};
static_assert(sizeof(LightView) == 112 && offsetof(LightView, boundsMin) == 64 &&
              offsetof(LightView, view) == 96 && offsetof(LightView, reversedZ) == 108);

// CameraUniform, shared with chapter-14, is common::CameraUniform (common/passes/camera_frames.hpp).
