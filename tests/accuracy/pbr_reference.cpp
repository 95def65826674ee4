// fp64 twin of shaders/include/pbr.glsl.
#include "tests/accuracy/pbr_reference.hpp"

#include <algorithm>
#include <cmath>

namespace common::pbr {

dvec3 safeNormalize(dvec3 v, dvec3 fallback) {
    double lengthSquared = glm::dot(v, v);
    // The GPU's threshold (1e-24 in fp32) is kept so both take the fallback on the same inputs.
    return lengthSquared > 1.0e-24 ? v / std::sqrt(lengthSquared) : fallback;
}

double distributionGGX(dvec3 N, dvec3 H, double NdotH, double roughness) {
    dvec3 NxH = glm::cross(N, H);
    double oneMinusNdotHSquared = glm::dot(NxH, NxH);
    double alpha = roughness * roughness;
    double a = NdotH * alpha;
    double k = alpha / (oneMinusNdotHSquared + a * a);
    return k * k * (1.0 / kPi);
}

double visibilitySmithSchlick(double NdotV, double NdotL, double roughness) {
    double r = roughness + 1.0;
    double k = r * r / 8.0;
    return 1.0 / (4.0 * (NdotV * (1.0 - k) + k) * (NdotL * (1.0 - k) + k));
}

dvec3 fresnelSchlick(double cosTheta, dvec3 F0) {
    return F0 + (1.0 - F0) * std::pow(std::clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

BrdfTerms cookTorranceTerms(dvec3 N, dvec3 V, dvec3 L, dvec3 albedo, double metallic, double roughness) {
    BrdfTerms t;
    t.NdotL = glm::dot(N, L);
    if (!(t.NdotL > 0.0)) return t;
    t.valid = true;
    t.NdotL = std::min(t.NdotL, 1.0);
    dvec3 h = V + L;
    dvec3 H = glm::dot(h, h) > kMinHalfVectorLengthSquared ? glm::normalize(h) : N;
    double NdotV = std::clamp(glm::dot(N, V), 0.0, 1.0);
    double NdotH = std::clamp(glm::dot(N, H), 0.0, 1.0);
    double HdotV = std::clamp(glm::dot(H, V), 0.0, 1.0);
    double r = std::clamp(roughness, kMinPerceptualRoughness, 1.0);
    dvec3 F0 = glm::mix(dvec3(0.04), albedo, std::clamp(metallic, 0.0, 1.0));
    t.F = fresnelSchlick(HdotV, F0);
    t.D = distributionGGX(N, H, NdotH, r);
    t.Vis = visibilitySmithSchlick(NdotV, t.NdotL, r);
    return t;
}

dvec3 cookTorrance(dvec3 N, dvec3 V, dvec3 L, dvec3 radiance, dvec3 albedo, double metallic,
                   double roughness) {
    BrdfTerms t = cookTorranceTerms(N, V, L, albedo, metallic, roughness);
    if (!t.valid) return dvec3(0.0);
    dvec3 specular = t.D * t.Vis * t.F;
    dvec3 kD = (dvec3(1.0) - t.F) * (1.0 - std::clamp(metallic, 0.0, 1.0));
    return (kD * albedo / kPi + specular) * radiance * t.NdotL;
}

bool incidentLight(bool directional, dvec3 positionOrDirection, dvec3 worldPos, dvec3& L,
                   double& attenuation) {
    attenuation = 1.0;
    if (directional) {
        L = safeNormalize(-positionOrDirection, dvec3(0.0));
        return true;
    }
    dvec3 toLight = positionOrDirection - worldPos;
    double distanceSquared = glm::dot(toLight, toLight);
    L = dvec3(0.0);
    if (!(distanceSquared > 0.0)) return false;
    L = toLight / std::sqrt(distanceSquared);
    attenuation = 1.0 / std::max(distanceSquared, kMinLightDistanceSquared);
    return true;
}

dvec3 evaluateLight(bool directional, dvec3 positionOrDirection, dvec3 color, double intensity,
                    dvec3 worldPos, dvec3 N, dvec3 V, dvec3 albedo, double metallic, double roughness) {
    dvec3 L;
    double attenuation;
    if (!incidentLight(directional, positionOrDirection, worldPos, L, attenuation)) return dvec3(0.0);
    return cookTorrance(N, V, L, color * intensity * attenuation, albedo, metallic, roughness);
}

double rangeWindow(double distanceSquared, double range) {
    if (range <= 0.0) return 1.0;
    double ratioSquared = distanceSquared / (range * range);
    double smoothed = std::clamp(1.0 - ratioSquared * ratioSquared, 0.0, 1.0);
    return smoothed * smoothed;
}

dvec3 surfaceNormal(dvec3 stored) {
    return safeNormalize(stored, dvec3(0.0, 0.0, 1.0));
}

dvec3 viewDirection(dvec3 worldPos, dvec3 cameraPosition, dvec3 N) {
    return safeNormalize(cameraPosition - worldPos, N);
}

}  // namespace common::pbr
