// chapter-15-lab: the G-buffer layouts beyond the book's, and reversed-Z.
#include "gbuffer_layouts.hpp"

#include <algorithm>

namespace {

// chapter-15's layout, with chapter-15's shaders (compiled into the lab's directory).
constexpr LabLayout kBookLayout{
    .layout = kBookGBuffer,
    .summary = "the book's: position, albedo, normal, AO/roughness/metallic, all RGBA16F",
    .shaderSuffix = "",
};

//> gbuffer-layouts
// The book's layout in RGBA32F: the accuracy yardstick (4 x 16 + 4 = 68 bytes per pixel).
constexpr LabLayout kReferenceGBuffer{
    .layout = {.name = "reference",
               .formats = {.position = VK_FORMAT_R32G32B32A32_SFLOAT,
                           .albedo = VK_FORMAT_R32G32B32A32_SFLOAT,
                           .normal = VK_FORMAT_R32G32B32A32_SFLOAT,
                           .pbr = VK_FORMAT_R32G32B32A32_SFLOAT,
                           .depth = VK_FORMAT_D32_SFLOAT},
               .reversedZ = false},
    .summary = "the book's attachments in RGBA32F",
    .shaderSuffix = "",
};

// Compact: albedo 3 x 10 bits (stored as its square root, gamma 2) + 2 bits of coverage, the
// normal octahedral in 2 x 16 bits, roughness and metallic in 2 x 16 bits, and no position: the
// light pass reconstructs it from reversed-Z depth (3 x 4 + 4 = 16 bytes per pixel).
constexpr LabLayout kCompactGBuffer{
    .layout = {.name = "compact",
               .formats = {.position = VK_FORMAT_UNDEFINED,
                           .albedo = VK_FORMAT_A2B10G10R10_UNORM_PACK32,
                           .normal = VK_FORMAT_R16G16_UNORM,
                           .pbr = VK_FORMAT_R16G16_UNORM,
                           .depth = VK_FORMAT_D32_SFLOAT},
               .reversedZ = true},
    .summary = "albedo 10 bits, octahedral normal, roughness/metallic 16 bits, position from depth",
    .shaderSuffix = "-compact",  // scene_compact.frag; light_shading.glsl with COMPACT_GBUFFER
};
//< gbuffer-layouts

}  // namespace

const GBufferLayout kForwardDepthOnly{
    .name = "depth only",
    .formats = {.position = VK_FORMAT_UNDEFINED,
                .albedo = VK_FORMAT_UNDEFINED,
                .normal = VK_FORMAT_UNDEFINED,
                .pbr = VK_FORMAT_UNDEFINED,
                .depth = VK_FORMAT_D32_SFLOAT},
    .reversedZ = false,
};

const std::vector<const LabLayout*>& labLayouts() {
    static const std::vector<const LabLayout*> layouts{&kBookLayout, &kReferenceGBuffer, &kCompactGBuffer};
    return layouts;
}

std::vector<std::string> labLayoutNames() {
    std::vector<std::string> names;
    for (const LabLayout* layout : labLayouts()) names.push_back(layout->layout.name);
    return names;
}

std::string labLayoutHelp() {
    std::string help = "G-buffer layout:";
    for (const LabLayout* layout : labLayouts())
        help += std::string(layout == labLayouts().front() ? " " : "; ") + layout->layout.name + ", " +
                layout->summary + " (" + std::to_string(common::bytesPerPixel(layout->layout.formats)) +
                " B/px)";
    return help;
}

SceneShaders labSceneShaders(const LabLayout& layout) {
    return {.vertex = "chapter-15-lab/scene.vert",
            .fragment = std::string("chapter-15-lab/") +
                        (layout.shaderSuffix[0] ? "scene_compact.frag" : "scene.frag")};
}

std::string labLightShader(const LabLayout& layout, const char* stage, bool tiled) {
    return std::string("chapter-15-lab/light") + layout.shaderSuffix + (tiled ? "-tiled." : ".") + stage;
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
