// --camera-motion and --light-motion (test_motion.hpp).
#include "common/app/test_motion.hpp"

namespace common {

TestMotion testMotion(const Options& options) {
    auto chosen = [&](const Choice& choice) {
        auto found = options.choices.find(choice.name);
        return found == options.choices.end() ? 0u : found->second;
    };
    return {.camera = CameraMotion(chosen(kCameraMotionChoice)),
            .light = LightMotion(chosen(kLightMotionChoice))};
}

void moveForTesting(const TestMotion& motion, uint32_t frame, Camera& camera, LightControls& controls,
                    Scene& scene, GpuScene& gpuScene) {
    glm::vec3 forward = cameraForward(camera);
    switch (motion.camera) {
        case CameraMotion::Walk:
            camera.position += forward * 0.02f;
            break;
        case CameraMotion::Creep:
            camera.position += forward * 1e-4f;
            break;
        case CameraMotion::Turn:
            camera.yaw += 0.5f;
            break;
        case CameraMotion::Jump:  // a walk, and every 8th frame 5 m forward or back
            camera.position += forward * 0.02f;
            if (frame % 8 == 7) camera.position += forward * (frame % 16 == 7 ? 5.0f : -5.0f);
            break;
        case CameraMotion::Still:
            break;
    }
    bool lightWalks =
        motion.light == LightMotion::Walk || (motion.light == LightMotion::WalkStop && frame < 30);
    if (lightWalks && controls.point >= 0) {
        glm::vec3 step = glm::normalize(glm::vec3(forward.x, 0.0f, forward.z) + glm::vec3(1e-6f, 0.0f, 0.0f));
        glm::vec3 position = scene.lights[size_t(controls.point)].position - step * 0.05f;
        placePointLight(controls, scene, gpuScene, position);
    }
}

}  // namespace common
