// chapter-15, beyond the book: the G-buffer layouts other than the book's, and the reversed-Z
// projection the compact one uses.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "common/camera.hpp"
#include "common/gpu_scene.hpp"
#include "common/scene.hpp"

// A camera projection and the planes it was made with.
struct Projection {
    glm::mat4 matrix;
    float near, far;
};

// Reversed-Z (near at depth 1, far at 0: float depth is then nearly as precise far away as close
// by), with the planes fitted to the scene's bounds as seen from the camera.
Projection reversedZProjection(const common::Scene& scene, const common::Camera& camera,
                               const common::GpuScene& gpuScene, VkExtent2D extent);
