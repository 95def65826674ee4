// Structs that C++ writes and chapter-15's shaders read. Their C++ twins are in
// chapter-15/gpu_types.hpp, next to this file's name; the layout test (tests/layout_test.cpp)
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
    float range;  // beyond the book: a point light's reach (0: unbounded, the book's falloff)
};

// Per-frame scene information: a uniform buffer, scalar layout too. 36 bytes.
struct ShaderSceneInfo {
    vec3 cameraPosition;
    float ambientIntensity;
    vec3 ambientColor;
    uint lightCount;  // the loop runs over the scene's actual lights only
    uint unboundedLightCount;  // beyond the book (tiled culling): the first lights, shaded everywhere
};

// Materials: a storage buffer, std430 layout. 48 bytes.
const uint MATERIAL_NORMAL_MAP = 1u;       // flags: the material has a normal map
const uint MATERIAL_METAL_ROUGH_MAP = 2u;  //        ... a metal-rough map
const uint MATERIAL_OCCLUSION_MAP = 4u;    //        ... an occlusion map (glTF)
const uint MATERIAL_DOUBLE_SIDED = 8u;     //        back faces are seen: their normals are flipped
struct ShaderMaterial {
    vec4 diffuse;
    float roughness;  // factors, multiplied by the metal-rough texture's when there is one
    float metallic;
    uint flags;       // the MATERIAL_ bits: textures not worth sampling are skipped
    float alphaCutoff;        // cut-outs: alpha below it is discarded
    float normalScale;        // glTF normalTexture.scale: scales the map's x and y
    float occlusionStrength;  // glTF occlusionTexture.strength: ao = 1 + strength * (sample - 1)
    vec2 padding;
};
//< gpu-types

// The camera: one uniform buffer per frame in flight (std140), set 0 of the scene pass. C++:
// common::CameraUniform (common/camera.hpp).
struct CameraUniform {
    mat4 projection;
    mat4 view;
};

// The scene pass's vertex-stage push constants (std430): 112 bytes.
struct DrawConstants {
    mat4 model;         // bytes 0..63
    mat3 normalMatrix;  // bytes 64..111 (three 16-byte columns): inverse-transpose of the model matrix
};

// The light pass's push constants (std430): 112 bytes.
struct LightView {
    mat4 clipToCameraRelative;  // inverse of projection x (view without its translation)
    vec4 boundsMin;             // xyz: the scene's bounds, to show positions as colours
    vec4 boundsMax;
    int view;       // 0 final, 1 position, 2 albedo, 3 normal, 4 pbr, 5 depth
    float near;     // the projection's near and far planes
    float far;
    int reversedZ;  // depth 1 at near, 0 at far
};

// Beyond the book, --light-culling tiled (chapter-15/beyond/light_culling.cpp): the culling
// passes' view of the frame, one uniform buffer per frame in flight, scalar layout. 100 bytes.
// Pixels per tile side. 8 rather than the usual 16: a tile's list holds the lights of all its
// pixels, and when lights are small on screen (65,536 of them) 16x16 tiles list several times
// more lights than reach any one pixel (docs/performance.md, "Many lights").
const uint LIGHT_TILE_SIZE = 8u;
const uint TILE_OVERFLOW = 0xffffffffu;         // a tile whose list did not fit: it loops over every light
struct CullView {
    mat4 viewRotation;     // camera-relative world space to view space (looking along -z)
    vec2 projectionScale;  // the projection's [0][0] and [1][1]: view-space slope to NDC
    float near;            // the near plane: nothing closer is drawn
    float margin;          // how far a stored surface position may lie from its pixel's ray
    uvec2 tileCount;       // tiles across and down
    uvec2 extent;          // the G-buffer's size in pixels
    uint capacity;         // light indices the tile lists can hold, all tiles together
};

#endif
