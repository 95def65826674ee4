// The camera: view and projection matrices, and the book's controls in a window (W/A/S/D and
// Up/Down move, dragging with the right mouse button looks around). The book's Camera and
// Projection (chapters 7 and 9). Also the key presses that switch views and options.
#pragma once

#include <GLFW/glfw3.h>

#include <glm/glm.hpp>

#include <vector>

#include <vulkan/vulkan.h>

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
// `keys`, `mouse`: false while a GUI takes the keyboard or the mouse.
void moveCamera(GLFWwindow* window, Camera& camera, CameraInput& input, float seconds, float speed,
                bool keys = true, bool mouse = true);

// A key that switches something once per press (V: the next view, F: FXAA), however many frames
// it is held down.
struct KeyPress {
    int key;
    bool down = false;
};
// True on the first frame `press.key` is down.
bool pressedOnce(GLFWwindow* window, KeyPress& press);

}  // namespace common
