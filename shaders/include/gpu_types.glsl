// Structs that C++ writes and chapter-15's shaders read. Their C++ twins are in
// chapter-15/gpu_types.hpp, next to this file's name; the layout test (tests/chapters/layout_test.cpp)
// checks that both sides agree on every size and offset.
#ifndef GPU_TYPES_GLSL
#define GPU_TYPES_GLSL

//> gpu-types
// Lights: a storage buffer with scalar layout (GL_EXT_scalar_block_layout): vec3 takes 12 bytes
// and aligns to 4, so this struct is 36 bytes with no padding.
struct ShaderLight {
    vec3 position;  // a point light's position; a directional light's travel direction
    uint directional;
    float intensity;
    vec3 color;
    float range;  // a point light's reach, from the scene (0: unbounded, the book's falloff)
};

// Per-frame scene information: a uniform buffer, scalar layout too. 32 bytes.
struct ShaderSceneInfo {
    vec3 cameraPosition;
    float ambientIntensity;
    vec3 ambientColor;
    uint lightCount;  // the loop runs over the scene's actual lights only
};

// Materials: a storage buffer, std430 layout. 48 bytes.
const uint MATERIAL_NORMAL_MAP = 1u;       // flags: the material has a normal map
const uint MATERIAL_METAL_ROUGH_MAP = 2u;  //        ... a metal-rough map
const uint MATERIAL_OCCLUSION_MAP = 4u;    //        ... an occlusion map (glTF)
const uint MATERIAL_DOUBLE_SIDED = 8u;     //        back faces are seen: their normals are flipped
const uint MATERIAL_BASE_COLOR_MAP = 16u;  //        a base-colour (albedo) texture
const uint MATERIAL_NORMAL_SCALE = 32u;    //        a normal map whose scale is not 1 (glTF)
struct ShaderMaterial {
    vec4 diffuse;
    float roughness;  // factors, multiplied by the metal-rough texture's when there is one
    float metallic;
    uint flags;       // the MATERIAL_ bits: the features the material uses (its class)
    float alphaCutoff;        // cut-outs: alpha below it is discarded
    float normalScale;        // glTF normalTexture.scale: scales the map's x and y
    float occlusionStrength;  // glTF occlusionTexture.strength: ao = 1 + strength * (sample - 1)
    vec2 padding;
};
//< gpu-types

// The camera: one uniform buffer per frame in flight (std140), set 0 of the scene pass. C++:
// common::CameraUniform (common/passes/camera_frames.hpp).
struct CameraUniform {
    mat4 projection;
    mat4 view;
};

// The scene pass's vertex-stage push constants (std430): 112 bytes.
struct DrawConstants {
    mat4 model;         // bytes 0..63
    mat3 normalMatrix;  // bytes 64..111 (three 16-byte columns): inverse-transpose of the model matrix
};
// The fragment stage's push constant, the draw's material index, follows the vertex stage's:
// at sizeof(DrawConstants). C++: kDrawMaterialOffset (chapter-15/gpu_types.hpp).
#ifndef DRAW_MATERIAL_OFFSET  // chapter-18 compiles the fragment shaders with its own (chapter-18/mesh_pulling.hpp)
#define DRAW_MATERIAL_OFFSET 112
#endif

// The light pass's push constants (std430): 112 bytes.
struct LightView {
    mat4 clipToCameraRelative;  // inverse of projection x (view without its translation): positions
                                // from depth, for a layout that stores none
    vec4 boundsMin;             // xyz: the scene's bounds, to show positions as colours
    vec4 boundsMax;
    int view;       // 0 final, 1 position, 2 albedo, 3 normal, 4 pbr, 5 depth
    float near;     // the projection's near and far planes
    float far;
    int reversedZ;  // the layout's depth: 1 at near, 0 at far (else 0 at near)
};

#endif
