// The camera: view and projection matrices, and the book's controls in a window (W/A/S/D and
// Up/Down move, dragging with the right mouse button looks around). The book's Camera and
// Projection (chapters 7 and 9). Also the key presses that switch views and options.
#pragma once

#include <GLFW/glfw3.h>

#include <glm/glm.hpp>

#include <vector>

#include "common/buffer.hpp"
#include "common/device.hpp"
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

// The camera as the scene passes of chapters 14 and 15 read it: set 0, binding 0, the twin of
// `uniform CameraUniform` in shaders/chapter-14/scene.vert and shaders/chapter-15/scene.vert
// (std140: two column-major mat4, 128 bytes; tests/layout_test.cpp checks it on the GPU).
struct CameraUniform {
    glm::mat4 projection;
    glm::mat4 view;
};
static_assert(sizeof(CameraUniform) == 128);

// One per frame in flight: the camera's host-visible uniform buffer, written every frame, and
// the descriptor set that binds it.
struct CameraFrame {
    Buffer buffer;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// The set layout: binding 0, a uniform buffer read by the vertex stage.
VkDescriptorSetLayout createCameraSetLayout(const Device& device);
// `pool` must have room for `framesInFlight` sets of one uniform buffer each.
std::vector<CameraFrame> createCameraFrames(const Device& device, VkDescriptorPool pool,
                                            VkDescriptorSetLayout layout, uint32_t framesInFlight);
void writeCamera(CameraFrame& frame, const glm::mat4& projection, const glm::mat4& view);
void destroyCameraFrames(const Device& device, std::vector<CameraFrame>& frames);

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
