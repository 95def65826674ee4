// chapter-15 scene pass: the surface a fragment shows -- albedo, shading normal (normal map
// applied), roughness, metallic, ambient occlusion -- from the draw's material and textures.
// scene.frag writes it into the G-buffer.

//> scene-surface
// One pipeline per material class the scene has (scene_pass.cpp): the features its materials
// use are fixed when the pipeline is made, so a feature no material of the draw uses compiles
// away -- a material with none of glTF's extras runs the book's steps and nothing more.
//   ALPHA_TEST: cut-outs; off for opaque materials, so the depth test can run before the shader
//     (only cut-outs pay for discard).
//   MATERIAL_FEATURES: the MATERIAL_ bits (gpu_types.glsl) of the draw's material class.
//   FEATURES_AT_RUN_TIME: the generic pipelines (--pipelines generic): one for any material,
//     asking each material's flags as the fragment runs. The default, so the SPIR-V without
//     constants draws every material right.
layout(constant_id = 0) const bool ALPHA_TEST = true;
layout(constant_id = 1) const uint MATERIAL_FEATURES = 0u;
layout(constant_id = 2) const bool FEATURES_AT_RUN_TIME = true;

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBitangent;
layout(location = 4) in vec2 inUv;

layout(std430, set = 1, binding = 0) readonly buffer Materials {
    ShaderMaterial materials[];
};
// The draw's material's textures (defaults: white, a flat normal map, white, white).
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;
layout(set = 2, binding = 1) uniform sampler2D normalTexture;
layout(set = 2, binding = 2) uniform sampler2D metalRoughTexture;
layout(set = 2, binding = 3) uniform sampler2D occlusionTexture;

layout(push_constant) uniform Draw {
    layout(offset = DRAW_MATERIAL_OFFSET) uint materialIndex;
} draw;

struct SceneSurface {
    vec3 albedo;
    vec3 normal;  // unit length, world space
    float roughness;
    float metallic;
    float ao;  // ambient occlusion: 1 unless an occlusion map darkens the ambient light
};

// Whether the draw's material uses `feature`: a constant in a specialised pipeline.
bool uses(ShaderMaterial material, uint feature) {
    return FEATURES_AT_RUN_TIME ? (material.flags & feature) != 0u : (MATERIAL_FEATURES & feature) != 0u;
}

SceneSurface sceneSurface() {
    SceneSurface surface;
    ShaderMaterial material = materials[draw.materialIndex];
    vec4 albedo = material.diffuse;
    if (uses(material, MATERIAL_BASE_COLOR_MAP)) albedo *= texture(albedoTexture, inUv);
    // A G-buffer pixel holds one surface: cut-outs are all or nothing (docs: transparency).
    if (ALPHA_TEST && albedo.a < material.alphaCutoff) discard;
    surface.albedo = albedo.rgb;

    vec3 N = safeNormalize(inNormal, vec3(0.0, 0.0, 1.0));
    // A double-sided material's back face is lit as a front face: its whole frame turns over
    // (glTF 2.0 specification, 3.9.5 "Double Sided").
    bool backFace = uses(material, MATERIAL_DOUBLE_SIDED) && !gl_FrontFacing;
    surface.normal = backFace ? -N : N;
    if (uses(material, MATERIAL_NORMAL_MAP)) {
        // The tangent frame, re-orthonormalised after interpolation: T made perpendicular to N
        // (Gram-Schmidt), B = N x T with the handedness the mesh gave it.
        vec3 T = safeNormalize(inTangent - N * dot(N, inTangent), abs(N.x) < 0.9 ? cross(N, vec3(1, 0, 0))
                                                                                  : cross(N, vec3(0, 1, 0)));
        T = safeNormalize(T, vec3(1.0, 0.0, 0.0));
        vec3 B = cross(N, T) * (dot(cross(N, T), inBitangent) < 0.0 ? -1.0 : 1.0);
        if (backFace) {
            N = -N;
            T = -T;
            B = -B;
        }
        vec3 mapped = texture(normalTexture, inUv).rgb * 2.0 - 1.0;  // tangent space, z out of the surface
        if (uses(material, MATERIAL_NORMAL_SCALE)) mapped.xy *= material.normalScale;  // glTF's scale
        surface.normal = safeNormalize(mat3(T, B, N) * mapped, N);
    }

    vec4 metalRough = uses(material, MATERIAL_METAL_ROUGH_MAP)
                          ? texture(metalRoughTexture, inUv)  // G roughness, B metallic (glTF and the book)
                          : vec4(1.0);
    surface.roughness = material.roughness * metalRough.g;
    surface.metallic = material.metallic * metalRough.b;
    surface.ao = uses(material, MATERIAL_OCCLUSION_MAP)
                     ? 1.0 + material.occlusionStrength * (texture(occlusionTexture, inUv).r - 1.0)
                     : 1.0;
    return surface;
}
//< scene-surface
