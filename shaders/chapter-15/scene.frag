#version 450
// chapter-15 scene pass: writes the book's G-buffer -- world position, albedo, normal (normal
// map applied) and PBR data (AO, roughness, metallic) -- one colour attachment each. Compiled a
// second time with COMPACT_GBUFFER for --gbuffer compact: no position (the light pass
// reconstructs it from depth), the normal octahedral-encoded in 2 x 16 bits, albedo in 3 x 10
// bits (gamma 2), roughness and metallic in 2 x 16 bits (AO is a constant: not stored).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "octahedral.glsl"
#include "pbr.glsl"

//> scene-frag
// Two pipelines from this shader: opaque materials compile the alpha test away, so the depth test
// can run before the shader; only cut-out materials (alpha below 1 somewhere) pay for discard.
layout(constant_id = 0) const bool ALPHA_TEST = true;

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBitangent;
layout(location = 4) in vec2 inUv;

#ifdef COMPACT_GBUFFER
layout(location = 0) out vec4 outAlbedo;  // A2B10G10R10_UNORM: sqrt(albedo), alpha = coverage
layout(location = 1) out vec2 outNormal;  // R16G16_UNORM, octahedral
layout(location = 2) out vec2 outPbr;     // R16G16_UNORM: roughness, metallic
#else
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outPbr;
#endif

layout(std430, set = 1, binding = 0) readonly buffer Materials {
    ShaderMaterial materials[];
};
// The draw's material's textures (defaults: white, a flat normal map, white).
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;
layout(set = 2, binding = 1) uniform sampler2D normalTexture;
layout(set = 2, binding = 2) uniform sampler2D metalRoughTexture;

layout(push_constant) uniform Draw {
    layout(offset = 112) uint materialIndex;
} draw;

void main() {
    ShaderMaterial material = materials[draw.materialIndex];
    vec4 albedo = material.diffuse * texture(albedoTexture, inUv);
    // A G-buffer pixel holds one surface: cut-outs are all or nothing (docs: transparency).
    if (ALPHA_TEST && albedo.a < 0.5) discard;

    // The tangent frame, re-orthonormalised after interpolation: T made perpendicular to N
    // (Gram-Schmidt), B = N x T with the handedness the mesh gave it.
    vec3 N = safeNormalize(inNormal, vec3(0.0, 0.0, 1.0));
    vec3 T = safeNormalize(inTangent - N * dot(N, inTangent), abs(N.x) < 0.9 ? cross(N, vec3(1, 0, 0))
                                                                              : cross(N, vec3(0, 1, 0)));
    T = safeNormalize(T, vec3(1.0, 0.0, 0.0));
    vec3 B = cross(N, T) * (dot(cross(N, T), inBitangent) < 0.0 ? -1.0 : 1.0);
    vec3 normal = N;
    if ((material.flags & MATERIAL_NORMAL_MAP) != 0u) {  // the same for the whole draw: cheap to branch on
        vec3 mapped = texture(normalTexture, inUv).rgb * 2.0 - 1.0;  // tangent space, z out of the surface
        normal = safeNormalize(mat3(T, B, N) * mapped, N);
    }

#ifdef COMPACT_GBUFFER
    outNormal = encodeOctahedral(normal);
#else
    outPosition = vec4(inWorldPosition, 1.0);
    outNormal = vec4(normal, 1.0);
#endif
    float ao = 0.5;  // fixed, as in the book (no AO maps yet); the lighting does not read it
    vec4 metalRough = (material.flags & MATERIAL_METAL_ROUGH_MAP) != 0u
                          ? texture(metalRoughTexture, inUv)  // G roughness, B metallic (glTF and the book)
                          : vec4(1.0);
    float roughness = material.roughness * metalRough.g, metallic = material.metallic * metalRough.b;
#ifdef COMPACT_GBUFFER
    // Gamma 2 puts the 10 bits where the eye needs them (dark values), like sRGB but cheap to undo.
    outAlbedo = vec4(sqrt(albedo.rgb), 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    outPbr = vec2(roughness, metallic);
#else
    outAlbedo = vec4(albedo.rgb, 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    outPbr = vec4(ao, roughness, metallic, 1.0);
#endif
}
//< scene-frag
