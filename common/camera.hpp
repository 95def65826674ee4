// The camera: view and projection matrices, and the book's controls in a window (W/A/S/D and
// Up/Down move, dragging with the right mouse button looks around). The book's Camera and
// Projection (chapters 7 and 9).
#pragma once

#include <GLFW/glfw3.h>

#include <glm/glm.hpp>

#include "common/scene.hpp"

namespace common {

struct Camera {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;    // degrees, see CameraDesc
    float pitch = 0.0f;  // degrees
};

glm::vec3 cameraForward(const Camera& camera);
glm::mat4 viewMatrix(const Camera& camera);
// Right-handed, depth 0..1, y up: meant for the flipped viewport every chapter sets.
glm::mat4 projectionMatrix(float fovDegrees, VkExtent2D extent, float near, float far);

// Mouse state between frames.
struct CameraInput {
    bool dragging = false;
    double lastX = 0.0, lastY = 0.0;
};

// Applies the keys held and the mouse moved since the last call; `speed` in units per second.
void moveCamera(GLFWwindow* window, Camera& camera, CameraInput& input, float seconds, float speed);

}  // namespace common
