// chapter-15-lab: the G-buffer layouts --gbuffer offers -- chapter-15's (the book's), the reference
// and the compact one -- each with the shaders that write and read it; the depth-only "layout" of
// forward shading; and the reversed-Z projection the compact layout uses.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"

struct LabLayout {
    GBufferLayout layout;
    const char* summary;       // for --help
    const char* shaderSuffix;  // the shader variant: "" (chapter-15's shaders) or "-compact"
};

// Every layout --gbuffer offers, the book's first (the default).
const std::vector<const LabLayout*>& labLayouts();
// Their names, in that order, and a --help line giving each one's bytes per pixel.
std::vector<std::string> labLayoutNames();
std::string labLayoutHelp();

// --shading forward writes no G-buffer: depth alone (4 bytes per pixel).
extern const GBufferLayout kForwardDepthOnly;

// The scene pass's shaders for a layout, and the light pass's (stage "frag" or "comp"; tiled: the
// variant that reads --light-culling tiled's lists): files under <build>/bin/shaders/chapter-15-lab/.
SceneShaders labSceneShaders(const LabLayout& layout);
std::string labLightShader(const LabLayout& layout, const char* stage, bool tiled);

// A camera projection and the planes it was made with.
struct Projection {
    glm::mat4 matrix;
    float near, far;
};

// Reversed-Z (near at depth 1, far at 0: float depth is then nearly as precise far away as close
// by), with the planes fitted to the scene's bounds as seen from the camera.
Projection reversedZProjection(const common::Scene& scene, const common::Camera& camera,
                               const common::GpuScene& gpuScene, VkExtent2D extent);
