// chapter-15, beyond the book: two more G-buffer layouts, the yardstick and the compact one
// (docs/accuracy.md measures both against an fp64 reference), and reversed-Z.
#include "beyond/gbuffer_layouts.hpp"

#include <algorithm>

#include "gbuffer_layout.hpp"

namespace {

//> gbuffer-layouts
// The book's layout in RGBA32F: the accuracy yardstick (4 x 16 + 4 = 68 bytes per pixel).
constexpr GBufferLayout kReferenceGBuffer{
    .name = "reference",
    .summary = "the book's attachments in RGBA32F",
    .formats = {.position = VK_FORMAT_R32G32B32A32_SFLOAT,
                .albedo = VK_FORMAT_R32G32B32A32_SFLOAT,
                .normal = VK_FORMAT_R32G32B32A32_SFLOAT,
                .pbr = VK_FORMAT_R32G32B32A32_SFLOAT,
                .depth = VK_FORMAT_D32_SFLOAT},
    .reversedZ = false,
    .shaderSuffix = "",
};

// Compact: albedo 3 x 10 bits (stored as its square root, gamma 2) + 2 bits of coverage, the
// normal octahedral in 2 x 16 bits, roughness and metallic in 2 x 16 bits, and no position: the
// light pass reconstructs it from reversed-Z depth (3 x 4 + 4 = 16 bytes per pixel).
constexpr GBufferLayout kCompactGBuffer{
    .name = "compact",
    .summary = "albedo 10 bits, octahedral normal, roughness/metallic 16 bits, position from depth",
    .formats = {.position = VK_FORMAT_UNDEFINED,
                .albedo = VK_FORMAT_A2B10G10R10_UNORM_PACK32,
                .normal = VK_FORMAT_R16G16_UNORM,
                .pbr = VK_FORMAT_R16G16_UNORM,
                .depth = VK_FORMAT_D32_SFLOAT},
    .reversedZ = true,
    .shaderSuffix = "-compact",  // scene.frag and light_shading.glsl compiled with COMPACT_GBUFFER
};
//< gbuffer-layouts

}  // namespace

const std::vector<const GBufferLayout*>& gbufferLayouts() {
    static const std::vector<const GBufferLayout*> layouts{&kBookGBuffer, &kReferenceGBuffer,
                                                           &kCompactGBuffer};
    return layouts;
}

std::vector<std::string> gbufferLayoutNames() {
    std::vector<std::string> names;
    for (const GBufferLayout* layout : gbufferLayouts()) names.push_back(layout->name);
    return names;
}

std::string gbufferLayoutHelp() {
    std::string help = "G-buffer layout:";
    for (const GBufferLayout* layout : gbufferLayouts())
        help += std::string(layout == gbufferLayouts().front() ? " " : "; ") + layout->name + ", " +
                layout->summary + " (" + std::to_string(common::bytesPerPixel(layout->formats)) + " B/px)";
    return help;
}

//> projection
Projection reversedZProjection(const common::Scene& scene, const common::Camera& camera,
                               const common::GpuScene& gpuScene, VkExtent2D extent) {
    glm::vec3 nearest = glm::clamp(camera.position, gpuScene.boundsMin, gpuScene.boundsMax);
    float far = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p((corner & 1) ? gpuScene.boundsMax.x : gpuScene.boundsMin.x,
                    (corner & 2) ? gpuScene.boundsMax.y : gpuScene.boundsMin.y,
                    (corner & 4) ? gpuScene.boundsMax.z : gpuScene.boundsMin.z);
        far = std::max(far, glm::length(p - camera.position));
    }
    far = far * 1.01f + 1e-3f;
    float near = std::max(glm::length(nearest - camera.position), far * 1e-5f);
    // Swapping the planes in the projection is all reversed-Z needs (plus GREATER and clear 0).
    return {common::projectionMatrix(scene.camera.fov, extent, far, near), near, far};
}
//< projection
