#version 450
// The numeric test of the shading math: the functions of pbr.glsl -- the very file chapter-15's
// light pass includes -- evaluated on a table of inputs, written out for comparison with their
// fp64 twins in tests/accuracy/pbr_reference.cpp (tests/accuracy/pbr_numeric_test.cpp).
#extension GL_GOOGLE_include_directive : require
#include "pbr.glsl"

layout(local_size_x = 64) in;

// One input: what the light pass has at a pixel for one light.
struct Sample {
    vec4 storedNormalRoughness;  // xyz: the normal as stored in the G-buffer, w: roughness
    vec4 worldPositionMetallic;  // xyz: world position, w: metallic
    vec4 cameraPosition;         // xyz
    vec4 lightPositionDirectional;  // xyz: position or direction, w: 1 for directional
    vec4 lightColorIntensity;    // xyz: colour, w: intensity
    vec4 albedo;                 // xyz
};
struct Result {
    vec4 terms;  // D, Vis, NdotL, valid (1 or 0)
    vec4 fresnel;
    vec4 radiance;  // evaluateLight: the full contribution of the light
};

layout(std430, set = 0, binding = 0) readonly buffer Samples { Sample samples[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { Result results[]; };
layout(push_constant) uniform Count { uint count; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    Sample s = samples[i];
    vec3 worldPosition = s.worldPositionMetallic.xyz;
    float metallic = s.worldPositionMetallic.w, roughness = s.storedNormalRoughness.w;
    bool directional = s.lightPositionDirectional.w != 0.0;

    // Exactly the light pass's steps.
    vec3 N = surfaceNormal(s.storedNormalRoughness.xyz);
    vec3 V = viewDirection(worldPosition, s.cameraPosition.xyz, N);
    vec3 L;
    float attenuation;
    BrdfTerms t;
    t.valid = false;
    t.NdotL = 0.0;
    t.D = 0.0;
    t.Vis = 0.0;
    t.F = vec3(0.0);
    if (incidentLight(directional, s.lightPositionDirectional.xyz, worldPosition, L, attenuation))
        t = cookTorranceTerms(N, V, L, s.albedo.xyz, metallic, roughness);
    results[i].terms = vec4(t.D, t.Vis, t.NdotL, t.valid ? 1.0 : 0.0);
    results[i].fresnel = vec4(t.F, 0.0);
    results[i].radiance = vec4(evaluateLight(directional, s.lightPositionDirectional.xyz, s.lightColorIntensity.xyz,
                                             s.lightColorIntensity.w, worldPosition, N, V, s.albedo.xyz, metallic,
                                             roughness), 0.0);
}
