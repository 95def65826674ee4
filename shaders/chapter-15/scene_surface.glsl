// chapter-15 scene pass: the surface a fragment shows -- albedo, shading normal (normal map
// applied), roughness, metallic, ambient occlusion -- from the draw's material and textures.
// scene.frag writes it into the G-buffer.

//> scene-surface
// Two kinds of pipeline from this shader (each with and without back-face culling): opaque
// materials compile the alpha test away, so the depth test can run before the shader; only
// cut-out materials (alpha below 1 somewhere) pay for discard.
layout(constant_id = 0) const bool ALPHA_TEST = true;

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
    layout(offset = 112) uint materialIndex;
} draw;

struct SceneSurface {
    vec3 albedo;
    vec3 normal;  // unit length, world space
    float roughness;
    float metallic;
    float ao;  // ambient occlusion: 1 unless an occlusion map darkens the ambient light
};

SceneSurface sceneSurface() {
    SceneSurface surface;
    ShaderMaterial material = materials[draw.materialIndex];
    vec4 albedo = material.diffuse * texture(albedoTexture, inUv);
    // A G-buffer pixel holds one surface: cut-outs are all or nothing (docs: transparency).
    if (ALPHA_TEST && albedo.a < material.alphaCutoff) discard;
    surface.albedo = albedo.rgb;

    // The tangent frame, re-orthonormalised after interpolation: T made perpendicular to N
    // (Gram-Schmidt), B = N x T with the handedness the mesh gave it.
    vec3 N = safeNormalize(inNormal, vec3(0.0, 0.0, 1.0));
    vec3 T = safeNormalize(inTangent - N * dot(N, inTangent), abs(N.x) < 0.9 ? cross(N, vec3(1, 0, 0))
                                                                              : cross(N, vec3(0, 1, 0)));
    T = safeNormalize(T, vec3(1.0, 0.0, 0.0));
    vec3 B = cross(N, T) * (dot(cross(N, T), inBitangent) < 0.0 ? -1.0 : 1.0);
    // A double-sided material's back face is lit as a front face: its whole frame turns over
    // (glTF 2.0 specification, 3.9.5 "Double Sided").
    if ((material.flags & MATERIAL_DOUBLE_SIDED) != 0u && !gl_FrontFacing) {
        N = -N;
        T = -T;
        B = -B;
    }
    surface.normal = N;
    if ((material.flags & MATERIAL_NORMAL_MAP) != 0u) {  // the same for the whole draw: cheap to branch on
        vec3 mapped = texture(normalTexture, inUv).rgb * 2.0 - 1.0;  // tangent space, z out of the surface
        mapped.xy *= material.normalScale;                           // glTF's scale (1 for OBJ)
        surface.normal = safeNormalize(mat3(T, B, N) * mapped, N);
    }

    vec4 metalRough = (material.flags & MATERIAL_METAL_ROUGH_MAP) != 0u
                          ? texture(metalRoughTexture, inUv)  // G roughness, B metallic (glTF and the book)
                          : vec4(1.0);
    surface.roughness = material.roughness * metalRough.g;
    surface.metallic = material.metallic * metalRough.b;
    surface.ao = (material.flags & MATERIAL_OCCLUSION_MAP) != 0u
                     ? 1.0 + material.occlusionStrength * (texture(occlusionTexture, inUv).r - 1.0)
                     : 1.0;
    return surface;
}
//< scene-surface
