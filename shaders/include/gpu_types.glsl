// Structs that C++ writes and chapter-15's shaders read. Their C++ twins are in
// chapter-15/gpu_types.hpp, next to this file's name; the layout test (tests/layout_test.cpp)
// checks that both sides agree on every size and offset.
#ifndef GPU_TYPES_GLSL
#define GPU_TYPES_GLSL

//> gpu-types
// Lights: a storage buffer with scalar layout (GL_EXT_scalar_block_layout): vec3 takes 12 bytes
// and aligns to 4, so this struct is 32 bytes with no padding.
struct ShaderLight {
    vec3 position;  // a point light's position; a directional light's travel direction
    uint directional;
    float intensity;
    vec3 color;
};

// Per-frame scene information: a uniform buffer, scalar layout too. 32 bytes.
struct ShaderSceneInfo {
    vec3 cameraPosition;
    float ambientIntensity;
    vec3 ambientColor;
    uint lightCount;  // the loop runs over the scene's actual lights only
};

// Materials: a storage buffer, std430 layout. 32 bytes.
const uint MATERIAL_NORMAL_MAP = 1u;       // flags: the material has a normal map
const uint MATERIAL_METAL_ROUGH_MAP = 2u;  //        ... a metal-rough map
struct ShaderMaterial {
    vec4 diffuse;
    float roughness;  // factors, multiplied by the metal-rough texture's when there is one
    float metallic;
    uint flags;       // the MATERIAL_ bits: textures not worth sampling are skipped
    float padding;
};
//< gpu-types

#endif
