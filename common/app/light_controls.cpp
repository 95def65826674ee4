// The book's chapter 15 light controls (common/app/light_controls.hpp).
#include "common/app/light_controls.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace common {

//> light-controls
LightControls findControlledLights(const Scene& scene) {
    LightControls controls;
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const Light& light = scene.lights[size_t(i)];
        if (light.type == Light::Type::Directional && controls.sun < 0) {
            controls.sun = i;
            // The heading: the direction's horizontal part, turned to +z's side (so a sun in the
            // y-z plane keeps the book's angle about the x axis); none, straight up or down: +z.
            glm::vec2 horizontal(light.direction.x, light.direction.z);
            float length = glm::length(horizontal);
            if (length > 1e-6f * glm::length(light.direction)) {
                glm::vec2 h = horizontal / length;
                if (h.y < 0.0f || (h.y == 0.0f && h.x < 0.0f)) h = -h;
                controls.sunHeading = {h.x, 0.0f, h.y};
            }
            float ahead = glm::dot(light.direction, controls.sunHeading);
            float angle = glm::degrees(std::atan2(light.direction.y, ahead));
            // Into the controls' 180..360: a sun along the horizon ahead is 360, not 0; one that
            // points up (outside the range) starts at the nearer horizon.
            if (angle < 0.0f) angle += 360.0f;
            if (angle <= 90.0f) angle = 360.0f;
            if (angle < 180.0f) angle = 180.0f;
            controls.sunAngle = angle;
        }
        if (light.type == Light::Type::Point && controls.point < 0) controls.point = i;
    }
    return controls;
}

void setSunAngle(LightControls& controls, Scene& scene, float degrees) {
    controls.sunAngle = glm::clamp(degrees, 180.0f, 360.0f);
    float radians = glm::radians(controls.sunAngle);
    scene.lights[size_t(controls.sun)].direction =
        controls.sunHeading * std::cos(radians) + glm::vec3(0.0f, std::sin(radians), 0.0f);
    controls.moved = true;
}

void placePointLight(LightControls& controls, Scene& scene, GpuScene& gpuScene, glm::vec3 position) {
    Light& light = scene.lights[size_t(controls.point)];
    light.position = position;
    controls.moved = true;
    if (light.marker < 0) return;
    Transform transform = scene.models[size_t(light.marker)].transform;
    transform.position = light.position;
    glm::mat4 matrix = transform.matrix();
    for (Draw& draw : gpuScene.draws) {
        if (draw.instance != uint32_t(light.marker)) continue;
        setDrawModel(gpuScene, draw, matrix);
        // The scene's bounds grow to hold the marker where it went: chapter-16's last cascade
        // ends where they do.
        const GpuMesh& mesh = gpuScene.meshes[draw.mesh];
        for (int i = 0; i < 8; ++i) {
            glm::vec3 world =
                glm::vec3(matrix * glm::vec4(boxCorner(i, mesh.boundsMin, mesh.boundsMax), 1.0f));
            gpuScene.boundsMin = glm::min(gpuScene.boundsMin, world);
            gpuScene.boundsMax = glm::max(gpuScene.boundsMax, world);
        }
    }
}

void moveLights(GLFWwindow* window, LightControls& controls, Scene& scene, GpuScene& gpuScene, float seconds,
                float speed) {
    // A stalled frame (a window dragged, a breakpoint, a busy machine) moves the lights by a tenth
    // of a second's worth at most, not by the whole stall.
    seconds = std::min(seconds, 0.1f);
    auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    if (controls.sun >= 0 && (held(GLFW_KEY_LEFT) || held(GLFW_KEY_RIGHT)))
        setSunAngle(controls, scene, controls.sunAngle + (held(GLFW_KEY_RIGHT) ? 45.0f : -45.0f) * seconds);
    if (controls.point < 0) return;
    glm::vec3 step(0.0f);
    if (held(GLFW_KEY_1)) step.y += 1.0f;
    if (held(GLFW_KEY_2)) step.y -= 1.0f;
    if (held(GLFW_KEY_3)) step.z -= 1.0f;
    if (held(GLFW_KEY_4)) step.z += 1.0f;
    if (step == glm::vec3(0.0f)) return;
    placePointLight(controls, scene, gpuScene,
                    scene.lights[size_t(controls.point)].position + step * speed * seconds);
}
//< light-controls

void beginLightsWindow(LightControls& controls, Scene& scene, GpuScene& gpuScene) {
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 10.0f, 10.0f), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::Begin("Lights", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    ImGui::PushItemWidth(180.0f);
    float angle = controls.sunAngle;
    if (controls.sun >= 0 && ImGui::SliderFloat("sun angle", &angle, 180.0f, 360.0f, "%.0f deg"))
        setSunAngle(controls, scene, angle);
    if (controls.point >= 0) {
        Light& point = scene.lights[size_t(controls.point)];
        glm::vec3 position = point.position;
        if (ImGui::DragFloat3("point light", &position.x, 0.05f))
            placePointLight(controls, scene, gpuScene, position);
        if (ImGui::ColorEdit3("colour", &point.color.x)) controls.moved = true;
    }
    ImGui::SliderFloat("ambient", &scene.ambientIntensity, 0.0f, 1.0f);
}

void endLightsWindow() {
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace common
