// chapter-15: deferred rendering II, PBR -- the book's chapter 15 in C++.
//
// chapter-14's frame with a full PBR G-buffer and real lighting:
//   scene pass (scene_pass.cpp): world position, albedo, normal (normal maps through the TBN
//     matrix) and AO/roughness/metallic into four R16G16B16A16_SFLOAT attachments, plus depth;
//   light pass (light_pass.cpp): Cook-Torrance shading (shaders/include/pbr.glsl) of every pixel
//     by the scene's directional and point lights, from a scalar-layout storage buffer, plus
//     ambient light, into an R32G32B32A32_SFLOAT image;
//   post pass (common/post_pass.cpp): into the presentation image, FXAA optional.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/benchmark.hpp"
#include "common/camera.hpp"
#include "common/check.hpp"
#include "common/cli.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/gpu_scene.hpp"
#include "common/instance.hpp"
#include "common/pipeline.hpp"
#include "common/post_pass.hpp"
#include "common/scene.hpp"
#include "common/screenshot.hpp"
#include "common/target.hpp"
#include "gpu_types.hpp"
#include "light_pass.hpp"
#include "scene_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-15",
    "deferred rendering II: PBR G-buffer, normal maps, lights (the book's chapter 15)",
    {"final", "position", "albedo", "normal", "pbr", "depth"},  // the order of light.frag's `view`
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"}},
    {{"gbuffer",
      {"book", "reference", "compact"},
      "G-buffer layout: the book's (36 B/px), all fp32 (68 B/px), or compact (16 B/px)"},
     {"light-pass",
      {"fragment", "compute"},
      "light pass: the book's full-screen triangle, or a compute dispatch (the same shading)"},
     {"dump",
      {},
      "write the light output (and the G-buffer of the float layouts) as PFM files into this directory"}},
};

//> light-controls
// The book's controls: Left/Right turn the directional light about the x axis, its angle kept
// within 180..360 degrees (270 is straight down); 1/2 move the point light up/down, 3/4 along z.
// The point light's marker model follows it.
struct LightControls {
    int sun = -1;    // index of the first directional light, if any
    int point = -1;  // index of the first point light, if any
    float sunAngle = 270.0f;
    bool moved = false;
};

LightControls findControlledLights(const common::Scene& scene) {
    LightControls controls;
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const common::Light& light = scene.lights[size_t(i)];
        if (light.type == common::Light::Type::Directional && controls.sun < 0) {
            controls.sun = i;
            float angle = glm::degrees(std::atan2(light.direction.y, light.direction.z));
            controls.sunAngle = angle < 0.0f ? angle + 360.0f : angle;
        }
        if (light.type == common::Light::Type::Point && controls.point < 0) controls.point = i;
    }
    return controls;
}

void moveLights(GLFWwindow* window, LightControls& controls, common::Scene& scene, common::GpuScene& gpuScene,
                float seconds, float speed) {
    auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    if (controls.sun >= 0 && (held(GLFW_KEY_LEFT) || held(GLFW_KEY_RIGHT))) {
        controls.sunAngle += (held(GLFW_KEY_RIGHT) ? 45.0f : -45.0f) * seconds;
        controls.sunAngle = glm::clamp(controls.sunAngle, 180.0f, 360.0f);
        float radians = glm::radians(controls.sunAngle);
        scene.lights[size_t(controls.sun)].direction = {0.0f, std::sin(radians), std::cos(radians)};
        controls.moved = true;
    }
    if (controls.point < 0) return;
    common::Light& light = scene.lights[size_t(controls.point)];
    glm::vec3 step(0.0f);
    if (held(GLFW_KEY_1)) step.y += 1.0f;
    if (held(GLFW_KEY_2)) step.y -= 1.0f;
    if (held(GLFW_KEY_3)) step.z -= 1.0f;
    if (held(GLFW_KEY_4)) step.z += 1.0f;
    if (step == glm::vec3(0.0f)) return;
    light.position += step * speed * seconds;
    controls.moved = true;
    if (light.marker < 0) return;
    common::Transform transform = scene.models[size_t(light.marker)].transform;
    transform.position = light.position;
    for (common::Draw& draw : gpuScene.draws)
        if (draw.instance == uint32_t(light.marker)) draw.model = transform.matrix();
}
//< light-controls

//> projection
// The projection of this frame. The book's layouts use the scene camera's near and far planes;
// the compact layout uses reversed-Z (near at depth 1, far at 0: float depth is then nearly as
// precise far away as close by) with the planes fitted to the scene's bounds as seen from here.
struct Projection {
    glm::mat4 matrix;
    float near, far;
    bool reversed;
};

Projection projectionFor(GBufferLayout layout, const common::Scene& scene, const common::Camera& camera,
                         const common::GpuScene& gpuScene, VkExtent2D extent) {
    if (!reversedZ(layout))
        return {common::projectionMatrix(scene.camera.fov, extent, scene.camera.near, scene.camera.far),
                scene.camera.near, scene.camera.far, false};
    glm::vec3 nearest = glm::clamp(camera.position, gpuScene.boundsMin, gpuScene.boundsMax);
    float far = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p((corner & 1) ? gpuScene.boundsMax.x : gpuScene.boundsMin.x,
                    (corner & 2) ? gpuScene.boundsMax.y : gpuScene.boundsMin.y,
                    (corner & 4) ? gpuScene.boundsMax.z : gpuScene.boundsMin.z);
        far = std::max(far, glm::length(p - camera.position));
    }
    far = far * 1.01f + 1e-3f;
    float near = std::max(glm::length(nearest - camera.position), far * 1e-5f);
    // Swapping the planes in the projection is all reversed-Z needs (plus GREATER and clear 0).
    return {common::projectionMatrix(scene.camera.fov, extent, far, near), near, far, true};
}
//< projection

//> shader-lights
std::vector<ShaderLight> shaderLights(const common::Scene& scene) {
    std::vector<ShaderLight> lights;
    for (const common::Light& light : scene.lights) {
        bool directional = light.type == common::Light::Type::Directional;
        lights.push_back({directional ? light.direction : light.position, directional ? 1u : 0u,
                          light.intensity, light.color});
    }
    return lights;
}
//< shader-lights

// --check-output: every value of the light output must be a finite, non-negative number.
void checkLightOutput(const common::Device& device, const LightPass& lightPass) {
    std::vector<float> values =
        common::readFloatImage(device, lightPass.output.handle, kLightOutputFormat, lightPass.output.extent,
                               VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    size_t nan = 0, infinite = 0, negative = 0;
    float largest = 0.0f;
    for (size_t i = 0; i < values.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            float v = values[i + c];
            nan += std::isnan(v);
            infinite += std::isinf(v);
            negative += v < 0.0f;
            if (std::isfinite(v)) largest = std::max(largest, v);
        }
    std::printf("chapter-15: light output %ux%u: %zu NaN, %zu infinite, %zu negative; largest value %g\n",
                lightPass.output.extent.width, lightPass.output.extent.height, nan, infinite, negative,
                largest);
    if (nan + infinite + negative != 0)
        throw common::Failure("the light output has NaN, infinite or negative values");
}

// --dump DIR: the last frame's light output, light.pfm; the distance from the camera plane of
// each pixel's surface, distance.pfm (from the depth attachment: it tells which surface a layout
// sees); and -- for the layouts that store floats -- the G-buffer as position/albedo/normal/pbr.pfm
// plus coverage.pfm (1 where a surface is). The accuracy tools (tests/accuracy/) shade these on
// the CPU in double precision.
void dumpFrame(const common::Device& device, const LightPass& lightPass, const ScenePass& scenePass,
               const LightView& view, const std::filesystem::path& directory) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    VkExtent2D extent = lightPass.output.extent;
    common::writePfm(directory / "light.pfm", extent.width, extent.height,
                     common::readFloatImage(device, lightPass.output.handle, kLightOutputFormat, extent,
                                            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL),
                     3);
    std::vector<float> distance = common::readFloatImage(device, scenePass.gbuffer.depth.handle, kDepthFormat,
                                                         extent, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    for (size_t i = 0; i < distance.size();
         i += 4) {  // depth.glsl's eyeDistance(), planes swapped when reversed
        double n = view.reversedZ ? view.far : view.near, f = view.reversedZ ? view.near : view.far;
        distance[i] = float(n * f / (f - double(distance[i]) * (f - n)));
    }
    common::writePfm(directory / "distance.pfm", extent.width, extent.height, distance, 1);
    if (scenePass.layout == GBufferLayout::Compact) {
        // The compact normals, decoded (octahedral.glsl's decodeOctahedral): which surface each pixel shows.
        const common::Image& normals = scenePass.gbuffer.colors[1];
        std::vector<float> texels = common::readFloatImage(device, normals.handle, normals.format, extent,
                                                           VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        for (size_t i = 0; i < texels.size(); i += 4) {
            glm::vec2 p(texels[i] * 2.0f - 1.0f, texels[i + 1] * 2.0f - 1.0f);
            glm::vec3 n(p, 1.0f - std::abs(p.x) - std::abs(p.y));
            if (n.z < 0.0f)
                n = glm::vec3((1.0f - std::abs(n.y)) * (n.x >= 0 ? 1.0f : -1.0f),
                              (1.0f - std::abs(n.x)) * (n.y >= 0 ? 1.0f : -1.0f), n.z);
            n = glm::normalize(n);
            texels[i] = n.x, texels[i + 1] = n.y, texels[i + 2] = n.z;
        }
        common::writePfm(directory / "normal.pfm", extent.width, extent.height, texels, 3);
        return;
    }
    const char* names[] = {"position", "albedo", "normal", "pbr"};
    for (size_t i = 0; i < 4; ++i) {
        const common::Image& image = scenePass.gbuffer.colors[i];
        std::vector<float> texels = common::readFloatImage(device, image.handle, image.format, extent,
                                                           VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        common::writePfm(directory / (std::string(names[i]) + ".pfm"), extent.width, extent.height, texels,
                         3);
        if (i == 1) common::writePfm(directory / "coverage.pfm", extent.width, extent.height, texels, 1, 3);
    }
    std::printf("chapter-15: wrote %s\n", directory.c_str());
}

void run(const common::Options& options) {
    //> setup
    common::ModelCache models;
    common::Scene scene = common::sceneFromOptions(options, models);

    common::Target target = common::openTarget(options, "chapter-15: deferred rendering II, PBR");
    common::Instance instance =
        common::createInstance("chapter-15", options.validation, common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    // scalarBlockLayout: the lights and scene info are read with the C-like scalar layout;
    // maintenance4: the compute light pass (glslang declares its group size with LocalSizeId).
    common::Device device = common::createDevice(instance, target.surface, options.device,
                                                 {.dynamicRendering = true,
                                                  .synchronization2 = true,
                                                  .scalarBlockLayout = true,
                                                  .maintenance4 = true});
    common::createTargetImages(target, device);
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);

    common::GpuScene gpuScene =
        common::loadGpuScene(device, scene, models, {.normalMaps = true, .metalRoughMaps = true});
    models.clear();
    std::printf("chapter-15: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                gpuScene.draws.size(), static_cast<unsigned long long>(gpuScene.triangles),
                gpuScene.textures.size(), gpuScene.materials.size(), scene.lights.size());

    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-15");
    GBufferLayout layout =
        GBufferLayout(options.choices.count("gbuffer") ? options.choices.at("gbuffer") : 0);
    ScenePass scenePass = createScenePass(device, pipelineCache.handle, target.extent, gpuScene,
                                          options.framesInFlight, layout);
    LightPassKind lightKind =
        LightPassKind(options.choices.count("light-pass") ? options.choices.at("light-pass") : 0);
    LightPass lightPass =
        createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer, layout, lightKind,
                        options.framesInFlight, uint32_t(scene.lights.size()));
    common::PostPass postPass =
        common::createPostPass(device, pipelineCache.handle, target.format, lightPass.output);

    common::Camera camera{scene.camera.position, scene.camera.yaw, scene.camera.pitch};
    common::CameraInput cameraInput;
    LightControls lightControls = findControlledLights(scene);
    LightView lightView{.boundsMin = glm::vec4(gpuScene.boundsMin, 0.0f),
                        .boundsMax = glm::vec4(gpuScene.boundsMax, 0.0f),
                        .view = int(options.view)};
    bool fxaa = options.switches.count("fxaa") != 0;

    // --benchmark: timestamps around the three passes, and the frame statistics.
    common::GpuTimer gpuTimer =
        common::createGpuTimer(device, options.framesInFlight, {"scene", "light", "post"});
    common::FrameStats stats = common::createFrameStats(options, gpuTimer.passes);
    //< setup

    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;
        resizeScenePass(device, scenePass, target.extent);
        resizeLightPass(device, lightPass, target.extent, scenePass.gbuffer);
        common::resizePostPass(device, postPass, lightPass.output);
        return true;
    };

    //> frame-loop
    double lastTime = glfwGetTime();
    bool viewKeyDown = false, fxaaKeyDown = false;
    float sceneSize = glm::length(gpuScene.boundsMax - gpuScene.boundsMin);
    for (uint32_t frame = 0;;) {
        auto frameStart = std::chrono::steady_clock::now();
        bool lastFrame = common::pollTarget(target, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];

        if (target.window) {  // camera, lights; V cycles the views, F toggles FXAA
            double now = glfwGetTime();
            float seconds = float(now - lastTime);
            lastTime = now;
            common::moveCamera(target.window, camera, cameraInput, seconds, sceneSize * 0.15f);
            moveLights(target.window, lightControls, scene, gpuScene, seconds, sceneSize * 0.05f);
            bool viewKey = glfwGetKey(target.window, GLFW_KEY_V) == GLFW_PRESS;
            if (viewKey && !viewKeyDown) lightView.view = (lightView.view + 1) % int(kChapter.views.size());
            viewKeyDown = viewKey;
            bool fxaaKey = glfwGetKey(target.window, GLFW_KEY_F) == GLFW_PRESS;
            if (fxaaKey && !fxaaKeyDown) fxaa = !fxaa;
            fxaaKeyDown = fxaaKey;
        }

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        if (options.benchmark) common::readGpuTimer(device, gpuTimer, slot, stats);  // this slot's last frame
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));

        // This frame's uniforms: camera, lights (they may have moved), scene info.
        glm::mat4 view = common::viewMatrix(camera);
        Projection projection = projectionFor(layout, scene, camera, gpuScene, target.extent);
        setCamera(scenePass, slot, projection.matrix, view);
        lightView.clipToCameraRelative = glm::inverse(projection.matrix * glm::mat4(glm::mat3(view)));
        lightView.near = projection.near;
        lightView.far = projection.far;
        lightView.reversedZ = projection.reversed ? 1 : 0;
        updateLights(lightPass, slot, shaderLights(scene),
                     {camera.position, scene.ambientIntensity, scene.ambientColor, 0u});

        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
        if (options.benchmark) common::beginGpuTimer(gpuTimer, sync.commandBuffer, slot, frame);
        recordScenePass(sync.commandBuffer, scenePass, gpuScene, slot, camera.position);
        if (options.benchmark) common::markGpuPass(gpuTimer, sync.commandBuffer, slot, 0);
        recordLightPass(sync.commandBuffer, lightPass, slot, lightView);
        if (options.benchmark) common::markGpuPass(gpuTimer, sync.commandBuffer, slot, 1);
        common::recordPostPass(sync.commandBuffer, postPass, target, imageIndex, fxaa);
        if (options.benchmark) common::markGpuPass(gpuTimer, sync.commandBuffer, slot, 2);
        VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));

        VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                   .semaphore = sync.imageAvailable,
                                   .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = target.renderFinished[imageIndex],
                                     .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
        VkCommandBufferSubmitInfo commands{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                           .commandBuffer = sync.commandBuffer};
        VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = 1,
                             .pWaitSemaphoreInfos = &wait,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &commands,
                             .signalSemaphoreInfoCount = 1,
                             .pSignalSemaphoreInfos = &signal};
        VK_CHECK(vkQueueSubmit2(device.queue, 1, &submit, sync.inFlight));

        if (lastFrame && !options.screenshot.empty())
            common::saveScreenshot(device, target.images[imageIndex], target.format, target.extent,
                                   target.presentLayout, options.screenshot);
        bool current = common::presentTargetImage(target, device, imageIndex);
        if (frame == 0) stats.startupMs = common::millisecondsSinceStart();
        common::addCpuFrame(
            stats, frame,
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
        if (lastFrame) break;
        if (!current && !recreateTarget()) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    //< frame-loop
    if (options.benchmark) {
        for (uint32_t slot = 0; slot < options.framesInFlight; ++slot)
            common::readGpuTimer(device, gpuTimer, slot, stats);
        std::vector<std::pair<std::string, std::string>> info =
            common::benchmarkInfo(kChapter, options, device, target);
        info.push_back({"gbuffer_bytes_per_pixel", std::to_string(gbufferBytesPerPixel(layout))});
        common::reportBenchmark(stats, info);
    }

    if (lightControls.moved) {
        glm::vec3 p =
            lightControls.point >= 0 ? scene.lights[size_t(lightControls.point)].position : glm::vec3(0.0f);
        std::printf("chapter-15: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    lightControls.sunAngle, p.x, p.y, p.z);
    }
    if (options.switches.count("check-output")) checkLightOutput(device, lightPass);
    if (options.values.count("dump"))
        dumpFrame(device, lightPass, scenePass, lightView, options.values.at("dump"));

    //> teardown
    common::destroyGpuTimer(device, gpuTimer);
    common::savePipelineCache(device, pipelineCache);
    common::destroyPostPass(device, postPass);
    destroyLightPass(device, lightPass);
    destroyScenePass(device, scenePass);
    common::destroyPipelineCache(device, pipelineCache);
    common::destroyGpuScene(device, gpuScene);
    common::destroyFrameSync(device, frames);
    common::destroyTargetImages(target, device);
    common::destroyDevice(device);
    common::destroyTargetSurface(target, instance);
    common::destroyInstance(instance);
    common::closeTarget(target);
    //< teardown
}

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
