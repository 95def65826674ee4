#version 450
// chapter-15 scene pass: writes the book's G-buffer -- world position, albedo, normal (normal
// map applied) and PBR data (AO, roughness, metallic) -- one colour attachment each.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "pbr.glsl"

//> scene-frag
layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBitangent;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outPbr;

layout(std430, set = 1, binding = 0) readonly buffer Materials {
    Material materials[];
};
// The draw's material's textures (defaults: white, a flat normal map, white).
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;
layout(set = 2, binding = 1) uniform sampler2D normalTexture;
layout(set = 2, binding = 2) uniform sampler2D metalRoughTexture;

layout(push_constant) uniform Draw {
    layout(offset = 112) uint materialIndex;
} draw;

void main() {
    Material material = materials[draw.materialIndex];
    vec4 albedo = material.diffuse * texture(albedoTexture, inUv);
    // A G-buffer pixel holds one surface: cut-outs are all or nothing (docs: transparency).
    if (albedo.a < 0.5) discard;

    // The tangent frame, re-orthonormalised after interpolation: T made perpendicular to N
    // (Gram-Schmidt), B = N x T with the handedness the mesh gave it.
    vec3 N = safeNormalize(inNormal, vec3(0.0, 0.0, 1.0));
    vec3 T = safeNormalize(inTangent - N * dot(N, inTangent), abs(N.x) < 0.9 ? cross(N, vec3(1, 0, 0))
                                                                              : cross(N, vec3(0, 1, 0)));
    T = safeNormalize(T, vec3(1.0, 0.0, 0.0));
    vec3 B = cross(N, T) * (dot(cross(N, T), inBitangent) < 0.0 ? -1.0 : 1.0);
    vec3 mapped = texture(normalTexture, inUv).rgb * 2.0 - 1.0;  // tangent space, z out of the surface
    vec3 normal = safeNormalize(mat3(T, B, N) * mapped, N);

    vec4 metalRough = texture(metalRoughTexture, inUv);  // G roughness, B metallic (glTF and the book)
    float ao = 0.5;  // fixed, as in the book (no AO maps yet)
    outPosition = vec4(inWorldPosition, 1.0);
    outAlbedo = vec4(albedo.rgb, 1.0);
    outNormal = vec4(normal, 1.0);
    outPbr = vec4(ao, material.roughness * metalRough.g, material.metallic * metalRough.b, 1.0);
}
//< scene-frag
