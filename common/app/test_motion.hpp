// --camera-motion and --light-motion: the camera and the point light moved by fixed steps each
// frame, for the tests and benchmarks of what a moving view costs (chapter-16's shadow cache and
// the chapters after it). Not the book's: a reader's camera moves with the keys (common/scene/camera.hpp).
#pragma once

#include <cstdint>

#include "common/app/cli.hpp"
#include "common/app/light_controls.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"

namespace common {

inline const Choice kCameraMotionChoice{
    "camera-motion",
    {"still", "walk", "creep", "turn", "jump"},
    "(testing, benchmarks) move the camera every frame: walk 2 cm forward, creep 0.1 mm, turn 0.5 degrees "
    "about y, jump: walk, and every 8th frame 5 m forward or back"};
inline const Choice kLightMotionChoice{
    "light-motion",
    {"still", "walk", "walk-stop"},
    "(testing, benchmarks) move the point light (and its marker) 5 cm a frame toward the camera, level; "
    "walk-stop: for the first 30 frames only"};

enum class CameraMotion : uint32_t { Still, Walk, Creep, Turn, Jump };  // kCameraMotionChoice's order
enum class LightMotion : uint32_t { Still, Walk, WalkStop };            // kLightMotionChoice's order

struct TestMotion {
    CameraMotion camera = CameraMotion::Still;
    LightMotion light = LightMotion::Still;
};

// The two options' values (Still where not given).
TestMotion testMotion(const Options& options);
// Frame `frame`'s steps, before the frame's update.
void moveForTesting(const TestMotion& motion, uint32_t frame, Camera& camera, LightControls& controls,
                    Scene& scene, GpuScene& gpuScene);

}  // namespace common
