// Camera matrices and window controls.
#include "common/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace common {

glm::vec3 cameraForward(const Camera& camera) {
    float yaw = glm::radians(camera.yaw), pitch = glm::radians(camera.pitch);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::mat4 viewMatrix(const Camera& camera) {
    return glm::lookAt(camera.position, camera.position + cameraForward(camera), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 projectionMatrix(float fovDegrees, VkExtent2D extent, float near, float far) {
    float aspect = float(extent.width) / float(std::max(extent.height, 1u));
    return glm::perspective(glm::radians(fovDegrees), aspect, near, far);  // GLM_FORCE_DEPTH_ZERO_TO_ONE
}

void moveCamera(GLFWwindow* window, Camera& camera, CameraInput& input, float seconds, float speed) {
    glm::vec3 forward = cameraForward(camera);
    glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    float step = speed * seconds;
    auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    if (held(GLFW_KEY_W)) camera.position += forward * step;
    if (held(GLFW_KEY_S)) camera.position -= forward * step;
    if (held(GLFW_KEY_D)) camera.position += right * step;
    if (held(GLFW_KEY_A)) camera.position -= right * step;
    if (held(GLFW_KEY_UP)) camera.position.y += step;
    if (held(GLFW_KEY_DOWN)) camera.position.y -= step;

    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    bool dragging = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
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

}  // namespace common
