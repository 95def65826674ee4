// Cook-Torrance shading with the GGX distribution, the Smith-Schlick geometry term and
// Fresnel-Schlick, for directional and point lights: the one source of truth for the shading
// math. chapter-15's light pass includes it, and so do the numeric tests (a compute shader
// compared against an fp64 CPU version of the same formulas).
//
// The formulas are the book's (chapter 15, after LearnOpenGL's "PBR: Lighting"), made robust so
// that no input gives NaN, infinity or a negative value; docs/chapter-15.md states each change
// and its reason:
//   - perceptual roughness is clamped to 0.045 (Filament's MIN_PERCEPTUAL_ROUGHNESS): at 0 the
//     GGX peak is infinite (0/0 at N = H);
//   - 1 - NdotH^2 is computed as |N x H|^2 (Filament), which keeps its precision near NdotH = 1;
//   - the Smith-Schlick G is divided by 4 NdotV NdotL in closed form, so no epsilon is needed
//     (the book adds 0.0001 to the denominator, which biases grazing angles);
//   - a light behind the surface (NdotL <= 0) contributes nothing and is skipped, as is a point
//     light exactly at the shaded point; H falls back to N when V and L are (within 0.06 degrees)
//     opposite;
//   - the point-light falloff 1/d^2 is bounded by d >= 1 cm (Filament): 1/max(d^2, 1e-4);
//   - the point light's direction is normalize(light - P). The book subtracts P twice.
#ifndef PBR_GLSL
#define PBR_GLSL

//> pbr
const float PI = 3.14159265358979;
const float MIN_PERCEPTUAL_ROUGHNESS = 0.045;
const float MIN_LIGHT_DISTANCE_SQUARED = 1.0e-4;
// |V + L|^2 below which V and L count as opposite (less than 0.06 degrees apart from it): their
// half vector is undefined there, and fp32 rounding alone would otherwise pick an arbitrary one.
const float MIN_HALF_VECTOR_LENGTH_SQUARED = 1.0e-6;

// v / |v|, or `fallback` when v has no usable length (zero, or NaN).
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float lengthSquared = dot(v, v);
    return lengthSquared > 1.0e-24 ? v * inversesqrt(lengthSquared) : fallback;
}

// GGX / Trowbridge-Reitz normal distribution. roughness: perceptual (as stored), alpha = roughness^2.
float distributionGGX(vec3 N, vec3 H, float NdotH, float roughness) {
    vec3 NxH = cross(N, H);
    float oneMinusNdotHSquared = dot(NxH, NxH);
    float alpha = roughness * roughness;
    float a = NdotH * alpha;
    float k = alpha / (oneMinusNdotHSquared + a * a);
    return k * k * (1.0 / PI);
}

// Smith's geometry term with Schlick-GGX for direct light, k = (roughness + 1)^2 / 8, divided by
// the Cook-Torrance denominator 4 NdotV NdotL: G1(V) G1(L) / (4 NdotV NdotL) =
// 1 / (4 (NdotV (1 - k) + k) (NdotL (1 - k) + k)), finite for all NdotV, NdotL >= 0.
float visibilitySmithSchlick(float NdotV, float NdotL, float roughness) {
    float r = roughness + 1.0;
    float k = r * r / 8.0;
    return 1.0 / (4.0 * (NdotV * (1.0 - k) + k) * (NdotL * (1.0 - k) + k));
}

vec3 fresnelSchlick(float cosTheta, vec3 F0) {
    return F0 + (1.0 - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// The terms of Cook-Torrance for light arriving along L (unit, towards the light), seen from V
// (unit); `valid` is false when the light is behind the surface, and then it contributes nothing.
struct BrdfTerms {
    bool valid;
    float NdotL;
    float D;    // GGX distribution
    float Vis;  // Smith-Schlick G / (4 NdotV NdotL)
    vec3 F;     // Fresnel-Schlick
};

BrdfTerms cookTorranceTerms(vec3 N, vec3 V, vec3 L, vec3 albedo, float metallic, float roughness) {
    BrdfTerms t;
    t.valid = false;
    t.NdotL = dot(N, L);
    t.D = 0.0;
    t.Vis = 0.0;
    t.F = vec3(0.0);
    if (!(t.NdotL > 0.0)) return t;  // behind the surface (also catches NaN)
    t.valid = true;
    t.NdotL = min(t.NdotL, 1.0);
    vec3 h = V + L;  // V = -L has no half vector: N stands in
    vec3 H = dot(h, h) > MIN_HALF_VECTOR_LENGTH_SQUARED ? normalize(h) : N;
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    float NdotH = clamp(dot(N, H), 0.0, 1.0);
    float HdotV = clamp(dot(H, V), 0.0, 1.0);
    float r = clamp(roughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
    vec3 F0 = mix(vec3(0.04), albedo, clamp(metallic, 0.0, 1.0));
    t.F = fresnelSchlick(HdotV, F0);
    t.D = distributionGGX(N, H, NdotH, r);
    t.Vis = visibilitySmithSchlick(NdotV, t.NdotL, r);
    return t;
}

// Light reflected towards V from light arriving along L with `radiance` (colour x intensity x
// attenuation): Cook-Torrance specular plus Lambert diffuse, times NdotL.
vec3 cookTorrance(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 albedo, float metallic, float roughness) {
    BrdfTerms t = cookTorranceTerms(N, V, L, albedo, metallic, roughness);
    if (!t.valid) return vec3(0.0);
    vec3 specular = t.D * t.Vis * t.F;
    vec3 kD = (vec3(1.0) - t.F) * (1.0 - clamp(metallic, 0.0, 1.0));  // metals absorb what they refract
    return (kD * albedo / PI + specular) * radiance * t.NdotL;
}

// Where a light's light comes from at worldPos: L (unit, towards the light) and the attenuation.
// A directional light's `positionOrDirection` is the direction the light travels; a point
// light's is its position. False when a point light sits exactly at worldPos (no direction).
bool incidentLight(bool directional, vec3 positionOrDirection, vec3 worldPos, out vec3 L, out float attenuation) {
    attenuation = 1.0;
    if (directional) {
        L = safeNormalize(-positionOrDirection, vec3(0.0));
        return true;
    }
    vec3 toLight = positionOrDirection - worldPos;
    float distanceSquared = dot(toLight, toLight);
    L = vec3(0.0);
    if (!(distanceSquared > 0.0)) return false;
    L = toLight * inversesqrt(distanceSquared);
    attenuation = 1.0 / max(distanceSquared, MIN_LIGHT_DISTANCE_SQUARED);
    return true;
}

// One light's contribution at worldPos.
vec3 evaluateLight(bool directional, vec3 positionOrDirection, vec3 color, float intensity, vec3 worldPos, vec3 N,
                   vec3 V, vec3 albedo, float metallic, float roughness) {
    vec3 L;
    float attenuation;
    if (!incidentLight(directional, positionOrDirection, worldPos, L, attenuation)) return vec3(0.0);
    return cookTorrance(N, V, L, color * intensity * attenuation, albedo, metallic, roughness);
}

// The unit normal from a stored one (which a G-buffer format may have denormalised), and the
// unit direction to the camera; each with a fallback instead of NaN.
vec3 surfaceNormal(vec3 stored) {
    return safeNormalize(stored, vec3(0.0, 0.0, 1.0));
}

vec3 viewDirection(vec3 worldPos, vec3 cameraPosition, vec3 N) {
    return safeNormalize(cameraPosition - worldPos, N);
}
//< pbr

//> light-range
// Beyond the book: a point light with a range r reaches no further than r. Its inverse-square
// falloff is multiplied by a window that is 1 at the light, falls smoothly and reaches 0 with a
// zero slope at d = r, so no edge shows: (1 - (d/r)^4)^2, clamped to 0..1 (Filament's
// getSquareFalloff; Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes, uses
// the same window). range 0 means no range: the book's unbounded falloff.
float rangeWindow(float distanceSquared, float range) {
    if (range <= 0.0) return 1.0;
    float ratioSquared = distanceSquared / (range * range);
    float smoothed = clamp(1.0 - ratioSquared * ratioSquared, 0.0, 1.0);
    return smoothed * smoothed;
}

// evaluateLight for a light with a range: nothing at or beyond it (and no shading math spent).
vec3 evaluateLightInRange(bool directional, vec3 positionOrDirection, vec3 color, float intensity, float range,
                          vec3 worldPos, vec3 N, vec3 V, vec3 albedo, float metallic, float roughness) {
    if (directional || range <= 0.0)
        return evaluateLight(directional, positionOrDirection, color, intensity, worldPos, N, V, albedo, metallic,
                             roughness);
    vec3 toLight = positionOrDirection - worldPos;
    float window = rangeWindow(dot(toLight, toLight), range);
    if (!(window > 0.0)) return vec3(0.0);
    return evaluateLight(false, positionOrDirection, color, intensity * window, worldPos, N, V, albedo, metallic,
                         roughness);
}
//< light-range

#endif
