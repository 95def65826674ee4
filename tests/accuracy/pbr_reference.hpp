// The shading of shaders/include/pbr.glsl evaluated on the CPU in double precision: the yardstick
// the numeric tests and the reference renderer measure the GPU against. Every function mirrors the
// GLSL function of the same name, operation for operation; a change to one is a change to both.
#pragma once

#include <glm/glm.hpp>

namespace common::pbr {

using glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kMinPerceptualRoughness = 0.045;
inline constexpr double kMinLightDistanceSquared = 1.0e-4;
inline constexpr double kMinHalfVectorLengthSquared = 1.0e-6;

dvec3 safeNormalize(dvec3 v, dvec3 fallback);
double distributionGGX(dvec3 N, dvec3 H, double NdotH, double roughness);
double visibilitySmithSchlick(double NdotV, double NdotL, double roughness);
dvec3 fresnelSchlick(double cosTheta, dvec3 F0);

// The terms cookTorrance() combines. `valid` is false when the light is behind the surface
// (then the light contributes nothing).
struct BrdfTerms {
    bool valid = false;
    double NdotL = 0.0;
    double D = 0.0, Vis = 0.0;
    dvec3 F{0.0};
};
BrdfTerms cookTorranceTerms(dvec3 N, dvec3 V, dvec3 L, dvec3 albedo, double metallic, double roughness);
dvec3 cookTorrance(dvec3 N, dvec3 V, dvec3 L, dvec3 radiance, dvec3 albedo, double metallic,
                   double roughness);
bool incidentLight(bool directional, dvec3 positionOrDirection, dvec3 worldPos, dvec3& L,
                   double& attenuation);
dvec3 surfaceNormal(dvec3 stored);
dvec3 viewDirection(dvec3 worldPos, dvec3 cameraPosition, dvec3 N);
dvec3 evaluateLight(bool directional, dvec3 positionOrDirection, dvec3 color, double intensity,
                    dvec3 worldPos, dvec3 N, dvec3 V, dvec3 albedo, double metallic, double roughness);
// A point light's range window (pbr.glsl's rangeWindow): 1 for range 0 (no range).
double rangeWindow(double distanceSquared, double range);

}  // namespace common::pbr
