// The light controls of the book's chapter 15, shared by chapter-15, chapter-16 and the lab: in a
// window, Left/Right turn the sun (the first directional light) between the horizon behind it
// and the horizon ahead, 270 degrees being straight down; 1/2 move the point light (the first)
// up and down, 3/4 along z; and the overlay's "Lights" window does the same with sliders. The
// point light's marker model follows it. The sun turns in its own vertical plane: its heading
// (the direction's horizontal part) is kept, so a sun that comes from the side stays there.
#pragma once

#include <GLFW/glfw3.h>

#include <glm/glm.hpp>

#include <cstdint>

#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"

namespace common {

struct LightControls {
    int sun = -1;    // index of the first directional light, if any
    int point = -1;  // index of the first point light, if any
    // The sun's angle in its vertical plane: 180 and 360 the horizon (behind and ahead along
    // `sunHeading`), 270 straight down.
    float sunAngle = 270.0f;
    glm::vec3 sunHeading{0.0f, 0.0f, 1.0f};  // unit, horizontal; (0, 0, 1) for a sun with none
    bool moved = false;                      // a light changed this frame
};

// The help lines of these keys, for the overlay's timings window.
inline constexpr const char* kLightKeysHelp[] = {"Left/Right  turn the sun",
                                                 "1/2, 3/4  move the point light up/down, along z"};

LightControls findControlledLights(const Scene& scene);
// Clamps `degrees` to 180..360 and points the sun there, keeping its heading.
void setSunAngle(LightControls& controls, Scene& scene, float degrees);
// Moves the point light and its marker; the scene's bounds grow to hold the marker where it went.
void placePointLight(LightControls& controls, Scene& scene, GpuScene& gpuScene, glm::vec3 position);
// Applies the keys held: the sun at 45 degrees a second, the point light at `speed` a second.
void moveLights(GLFWwindow* window, LightControls& controls, Scene& scene, GpuScene& gpuScene, float seconds,
                float speed);
// The overlay's "Lights" window, at the top right: the sun's angle, the point light's place and
// colour, the ambient light. A chapter may add its own widgets before endLightsWindow().
void beginLightsWindow(LightControls& controls, Scene& scene, GpuScene& gpuScene);
void endLightsWindow();

}  // namespace common
