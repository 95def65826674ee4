// Camera matrices, the camera uniform buffers and window controls.
#include "common/scene/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

namespace common {

glm::vec3 cameraForward(const Camera& camera) {
    float yaw = glm::radians(camera.yaw), pitch = glm::radians(camera.pitch);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::mat4 viewMatrix(const Camera& camera) {
    glm::vec3 forward = cameraForward(camera);
    // The book's lookAt(position, position + forward) -- unless position is so far from the
    // origin that position + forward loses the direction (floats are 1 apart at 1.7e7, 2^27 at
    // 1e15): then the rotation comes from the forward direction itself, and the translation after.
    glm::vec3 kept = (camera.position + forward) - camera.position;
    if (glm::length(kept - forward) < 1e-3f)
        return glm::lookAt(camera.position, camera.position + forward, glm::vec3(0.0f, 1.0f, 0.0f));
    glm::mat4 rotation = glm::lookAt(glm::vec3(0.0f), forward, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::translate(rotation, -camera.position);
}

glm::mat4 projectionMatrix(float fovDegrees, VkExtent2D extent, float near, float far) {
    float aspect = float(extent.width) / float(std::max(extent.height, 1u));
    return glm::perspective(glm::radians(fovDegrees), aspect, near, far);  // GLM_FORCE_DEPTH_ZERO_TO_ONE
}

void moveCamera(GLFWwindow* window, Camera& camera, CameraInput& input, float seconds, float speed, bool keys,
                bool mouse) {
    glm::vec3 forward = cameraForward(camera);
    glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    float step = speed * seconds;
    auto held = [&](int key) { return keys && glfwGetKey(window, key) == GLFW_PRESS; };
    if (held(GLFW_KEY_W)) camera.position += forward * step;
    if (held(GLFW_KEY_S)) camera.position -= forward * step;
    if (held(GLFW_KEY_D)) camera.position += right * step;
    if (held(GLFW_KEY_A)) camera.position -= right * step;
    if (held(GLFW_KEY_UP)) camera.position.y += step;
    if (held(GLFW_KEY_DOWN)) camera.position.y -= step;

    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    // A drag that starts while the mouse is not ours (over a GUI) does not turn the camera.
    bool dragging =
        glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && (mouse || input.dragging);
    if (dragging && input.dragging) {
        constexpr float kDegreesPerPixel = 0.2f;
        camera.yaw += float(x - input.lastX) * kDegreesPerPixel;
        camera.pitch = std::clamp(camera.pitch - float(y - input.lastY) * kDegreesPerPixel, -89.0f, 89.0f);
        camera.yaw = std::remainder(camera.yaw, 360.0f);
    }
    input.dragging = dragging;
    input.lastX = x;
    input.lastY = y;
}

bool pressedOnce(GLFWwindow* window, KeyPress& press) {
    bool down = glfwGetKey(window, press.key) == GLFW_PRESS;
    bool pressed = down && !press.down;
    press.down = down;
    return pressed;
}

}  // namespace common
