// chapter-15: deferred rendering II, PBR -- the book's chapter 15 in C++.
//
// chapter-14's frame with a full PBR G-buffer and real lighting:
//   scene pass (scene_pass.cpp): world position, albedo, normal (normal maps through the TBN
//     matrix) and AO/roughness/metallic into four R16G16B16A16_SFLOAT attachments, plus depth;
//   light pass (light_pass.cpp): Cook-Torrance shading (shaders/include/pbr.glsl) of every pixel
//     by the scene's directional and point lights, from a scalar-layout storage buffer, plus
//     ambient light, into an R32G32B32A32_SFLOAT image;
//   post pass (common/post_pass.cpp): into the presentation image, FXAA optional;
//   GUI pass (common/gui_pass.cpp, --gui): the Dear ImGui overlay over it, as the book's GuiRender.
// What goes beyond the book -- the reference and compact G-buffer layouts with reversed-Z, the
// light pass as a compute dispatch, --check-output and --dump, light ranges and tiled light
// culling, forward shading to compare with -- is in beyond/, and enters this file only where an
// option selects it.
#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "beyond/forward_shading.hpp"
#include "beyond/gbuffer_layouts.hpp"
#include "beyond/light_culling.hpp"
#include "beyond/output_dump.hpp"
#include "common/benchmark.hpp"
#include "common/camera.hpp"
#include "common/check.hpp"
#include "common/cli.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/gpu_scene.hpp"
#include "common/gui.hpp"
#include "common/gui_pass.hpp"
#include "common/instance.hpp"
#include "common/pipeline.hpp"
#include "common/post_pass.hpp"
#include "common/run_control.hpp"
#include "common/scene.hpp"
#include "common/target.hpp"
#include "gbuffer_layout.hpp"
#include "gpu_types.hpp"
#include "light_pass.hpp"
#include "scene_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-15",
    "deferred rendering II: PBR G-buffer, normal maps, lights (the book's chapter 15)",
    {"final", "position", "albedo", "normal", "pbr", "depth"},  // the order of light.frag's `view`
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     common::kGuiSwitch},
    {{"gbuffer", gbufferLayoutNames(), gbufferLayoutHelp()},
     {"light-pass",
      {"fragment", "compute"},
      "light pass: the book's full-screen triangle, or a compute dispatch (the same shading)"},
     {"dump",
      {},
      "write the light output (and the G-buffer of the float layouts) as PFM files into this directory"},
     {"light-culling",
      {"none", "tiled"},
      "none: every pixel loops over every light (the book's); tiled: over the lights whose range reaches "
      "its 8x8-pixel tile, listed by compute passes each frame"},
     {"light-cutoff",
      {},
      "give each point light without a range the distance where its irradiance falls to this value "
      "(a positive number)"},
     {"orbit", {}, "turn the camera this many degrees (-360..360) about the vertical each frame"},
     {"shading",
      {"deferred", "forward"},
      "deferred: the G-buffer, then the light pass (the book's); "
      "forward: the scene pass shades each fragment with every light (no light pass, the G-buffer "
      "not written), to compare"},
     common::kGuiClickChoice},
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

void setSunAngle(LightControls& controls, common::Scene& scene, float degrees) {
    controls.sunAngle = glm::clamp(degrees, 180.0f, 360.0f);
    float radians = glm::radians(controls.sunAngle);
    scene.lights[size_t(controls.sun)].direction = {0.0f, std::sin(radians), std::cos(radians)};
    controls.moved = true;
}

void placePointLight(LightControls& controls, common::Scene& scene, common::GpuScene& gpuScene,
                     glm::vec3 position) {
    common::Light& light = scene.lights[size_t(controls.point)];
    light.position = position;
    controls.moved = true;
    if (light.marker < 0) return;
    common::Transform transform = scene.models[size_t(light.marker)].transform;
    transform.position = light.position;
    for (common::Draw& draw : gpuScene.draws)
        if (draw.instance == uint32_t(light.marker)) draw.model = transform.matrix();
}

void moveLights(GLFWwindow* window, LightControls& controls, common::Scene& scene, common::GpuScene& gpuScene,
                float seconds, float speed) {
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

//> overlay
// The overlay (--gui): the timings window with the view selector (common/gui.cpp), FXAA and,
// beyond the book, the G-buffer layout and the light pass's form (switched at the next frame);
// a second window with the book's light controls and the ambient light.
struct RendererChoice {
    int layout = 0;     // index into gbufferLayouts()
    int lightPass = 0;  // LightPassKind
};

void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa,
                    RendererChoice& renderer, LightControls& controls, common::Scene& scene,
                    common::GpuScene& gpuScene, bool deferred) {
    common::guiTimingsWindow(gui, run, deferred ? kChapter.views : std::vector<std::string>{"final"}, view,
                             {"V  cycles the views", "F  toggles FXAA", "Left/Right  turn the sun",
                              "1/2, 3/4  move the point light up/down, along z"});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    if (deferred) {  // beyond the book, --shading forward has neither
        common::guiCombo("G-buffer", gbufferLayoutNames(), &renderer.layout);
        common::guiCombo("light pass", {"fragment", "compute"}, &renderer.lightPass);
    }
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 10.0f, 10.0f), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::Begin("Lights", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    ImGui::PushItemWidth(180.0f);
    float angle = controls.sunAngle;
    if (controls.sun >= 0 && ImGui::SliderFloat("sun angle", &angle, 180.0f, 360.0f, "%.0f deg"))
        setSunAngle(controls, scene, angle);
    if (controls.point >= 0) {
        common::Light& point = scene.lights[size_t(controls.point)];
        glm::vec3 position = point.position;
        if (ImGui::DragFloat3("point light", &position.x, 0.05f))
            placePointLight(controls, scene, gpuScene, position);
        if (ImGui::ColorEdit3("colour", &point.color.x)) controls.moved = true;
    }
    ImGui::SliderFloat("ambient", &scene.ambientIntensity, 0.0f, 1.0f);
    ImGui::PopItemWidth();
    ImGui::End();
}
//< overlay

//> shader-lights
std::vector<ShaderLight> shaderLights(const common::Scene& scene) {
    std::vector<ShaderLight> lights;
    for (const common::Light& light : scene.lights) {
        bool directional = light.type == common::Light::Type::Directional;
        lights.push_back({directional ? light.direction : light.position, directional ? 1u : 0u,
                          light.intensity, light.color, directional ? 0.0f : light.range});
    }
    return lights;
}
//< shader-lights

void run(const common::Options& options) {
    //> setup
    common::ModelCache models;
    common::Scene scene = common::sceneFromOptions(options, models);
    // Beyond the book: light ranges from --light-cutoff, tiled culling, the camera turning.
    LightOptions lightOptions = readLightOptions(options, scene);
    bool forward = readShading(options) == Shading::Forward;  // beyond the book: --shading forward

    common::Target target = common::openTarget(options, "chapter-15: deferred rendering II, PBR");
    common::Instance instance =
        common::createInstance("chapter-15", options.validation, common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    // scalarBlockLayout: the feature this chapter needs -- the lights and the scene info are
    // read with the C-like scalar layout (gpu_types.hpp). maintenance4: beyond the book, for the
    // compute light pass (glslang declares its group size with LocalSizeId).
    common::Device device = common::createDevice(instance, target.surface, options.device,
                                                 {.dynamicRendering = true,
                                                  .synchronization2 = true,
                                                  .scalarBlockLayout = true,
                                                  .maintenance4 = true});
    common::createTargetImages(target, device);
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);

    common::GpuScene gpuScene = common::loadGpuScene(
        device, scene, models, {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true});
    models.clear();
    std::printf("chapter-15: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                gpuScene.draws.size(), static_cast<unsigned long long>(gpuScene.triangles),
                gpuScene.textures.size(), gpuScene.materials.size(), scene.lights.size());

    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-15");
    // The book's G-buffer, or (--gbuffer) one of the layouts beyond it: gbuffer_layout.hpp.
    RendererChoice renderer{int(options.choices.count("gbuffer") ? options.choices.at("gbuffer") : 0),
                            int(options.choices.count("light-pass") ? options.choices.at("light-pass") : 0)};
    RendererChoice active = renderer;  // what the passes were made for
    const GBufferLayout* layout = gbufferLayouts().at(size_t(renderer.layout));
    ScenePass scenePass = createScenePass(device, pipelineCache.handle, target.extent, gpuScene,
                                          options.framesInFlight, *layout);
    LightPassKind lightKind = LightPassKind(renderer.lightPass);
    LightCullingPass culling;  // beyond the book: --light-culling tiled
    if (lightOptions.culling == LightCulling::Tiled)
        culling = createLightCulling(device, target.extent, options.framesInFlight, boundedLightCount(scene),
                                     *layout, gpuScene.boundsMin, gpuScene.boundsMax);
    LightPass lightPass =
        createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer, *layout, lightKind,
                        options.framesInFlight, uint32_t(scene.lights.size()), culling.setLayout);
    if (culling.setLayout)
        createLightCullingPipelines(device, pipelineCache.handle, culling, lightPass, *layout);
    common::PostPass postPass =
        common::createPostPass(device, pipelineCache.handle, target.format, lightPass.output);
    ForwardPass forwardPass;  // beyond the book: --shading forward
    if (forward) forwardPass = createForwardPass(device, pipelineCache.handle, scenePass, lightPass);

    common::Camera camera{scene.camera.position, scene.camera.yaw, scene.camera.pitch};
    common::CameraInput cameraInput;
    LightControls lightControls = findControlledLights(scene);
    LightView lightView{.boundsMin = glm::vec4(gpuScene.boundsMin, 0.0f),
                        .boundsMax = glm::vec4(gpuScene.boundsMax, 0.0f),
                        .view = int(options.view),
                        .reversedZ = layout->reversedZ ? 1 : 0};
    bool fxaa = options.switches.count("fxaa") != 0;

    // --gui: Dear ImGui's context and input (common/gui.cpp) and the pass that draws it.
    common::Gui gui = common::createGui(options, target);
    common::GuiPass guiPass;
    if (gui.enabled)
        guiPass = common::createGuiPass(device, pipelineCache.handle, target.format, options.framesInFlight);

    // --frames, --resize, --benchmark (each pass timed), --screenshot.
    bool tiled = lightOptions.culling == LightCulling::Tiled;
    std::vector<std::string> passes{"scene", "light", "post"};
    if (tiled) passes.insert(passes.begin() + 1, "cull");
    if (forward) passes = {"forward", "post"};
    if (gui.enabled) passes.push_back("gui");
    common::RunControl run = common::createRunControl(options, device, passes);
    //< setup

    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;
        resizeScenePass(device, scenePass, target.extent);
        resizeLightPass(device, lightPass, target.extent, scenePass.gbuffer);
        if (tiled) resizeLightCulling(device, culling, target.extent);
        common::resizePostPass(device, postPass, lightPass.output);
        return true;
    };

    //> switch-renderer
    // Beyond the book, from the overlay: another G-buffer layout or light-pass form, live. Every
    // pass that depends on them is made again (the G-buffer with the scene pass); the scene, the
    // window and the run go on.
    auto switchRenderer = [&] {
        VK_CHECK(vkDeviceWaitIdle(device.handle));
        common::destroyPostPass(device, postPass);
        destroyLightPass(device, lightPass);
        if (tiled) destroyLightCulling(device, culling);
        destroyScenePass(device, scenePass);
        active = renderer;
        layout = gbufferLayouts().at(size_t(renderer.layout));
        lightKind = LightPassKind(renderer.lightPass);
        scenePass = createScenePass(device, pipelineCache.handle, target.extent, gpuScene,
                                    options.framesInFlight, *layout);
        if (tiled)
            culling =
                createLightCulling(device, target.extent, options.framesInFlight, boundedLightCount(scene),
                                   *layout, gpuScene.boundsMin, gpuScene.boundsMax);
        lightPass = createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer, *layout,
                                    lightKind, options.framesInFlight, uint32_t(scene.lights.size()),
                                    culling.setLayout);
        if (tiled) createLightCullingPipelines(device, pipelineCache.handle, culling, lightPass, *layout);
        postPass = common::createPostPass(device, pipelineCache.handle, target.format, lightPass.output);
        lightView.reversedZ = layout->reversedZ ? 1 : 0;
        std::printf("chapter-15: switched to the %s G-buffer, %s light pass\n", layout->name,
                    lightKind == LightPassKind::Compute ? "compute" : "fragment");
    };
    //< switch-renderer

    //> frame-loop
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
    float sceneSize = glm::length(gpuScene.boundsMax - gpuScene.boundsMin);
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(run, target, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];

        ImDrawData* overlay = common::drawGui(gui, target, frame, [&] {
            overlayWidgets(gui, run, &lightView.view, &fxaa, renderer, lightControls, scene, gpuScene,
                           !forward);
        });
        if (renderer.layout != active.layout || renderer.lightPass != active.lightPass) switchRenderer();
        bool keys = !common::guiWantsKeyboard(gui), mouse = !common::guiWantsMouse(gui);
        if (target.window) {  // camera, lights; V cycles the views, F toggles FXAA (unless the GUI has them)
            double now = glfwGetTime();
            float seconds = float(now - lastTime);
            lastTime = now;
            common::moveCamera(target.window, camera, cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
            if (keys) moveLights(target.window, lightControls, scene, gpuScene, seconds, sceneSize * 0.05f);
            if (common::pressedOnce(target.window, viewKey) && keys && !forward)  // forward: no views
                lightView.view = (lightView.view + 1) % int(kChapter.views.size());
            if (common::pressedOnce(target.window, fxaaKey) && keys) fxaa = !fxaa;
        }
        camera.yaw += lightOptions.orbitDegrees;  // --orbit (beyond the book): 0 unless asked

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::collectGpuTimes(run, device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));
        if (gui.enabled) common::updateGuiBuffers(device, guiPass, slot, overlay);

        // This frame's uniforms: camera, lights (they may have moved), scene info.
        glm::mat4 view = common::viewMatrix(camera);
        Projection projection =
            layout->reversedZ ? reversedZProjection(scene, camera, gpuScene, target.extent)
                              : Projection{common::projectionMatrix(scene.camera.fov, target.extent,
                                                                    scene.camera.near, scene.camera.far),
                                           scene.camera.near, scene.camera.far};
        setCamera(scenePass, slot, projection.matrix, view);
        lightView.clipToCameraRelative = glm::inverse(projection.matrix * glm::mat4(glm::mat3(view)));
        lightView.near = projection.near;
        lightView.far = projection.far;
        std::vector<ShaderLight> lights = shaderLights(scene);
        uint32_t unbounded =
            tiled ? putUnboundedFirst(lights) : 0u;  // beyond the book: tiled culling's order
        updateLights(lightPass, slot, lights,
                     {camera.position, scene.ambientIntensity, scene.ambientColor, 0u, unbounded});
        if (tiled)
            updateLightCulling(culling, slot, glm::mat4(glm::mat3(view)), projection.matrix, projection.near);

        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
        common::timeFrameStart(run, sync.commandBuffer, slot, frame);
        uint32_t pass = 0;
        if (forward) {  // beyond the book: --shading forward, the G-buffer not written
            recordForwardPass(sync.commandBuffer, forwardPass, scenePass, lightPass, gpuScene, slot,
                              camera.position);
            common::timePassEnd(run, sync.commandBuffer, slot, pass++);
        } else {
            recordScenePass(sync.commandBuffer, scenePass, gpuScene, slot, camera.position);
            common::timePassEnd(run, sync.commandBuffer, slot, pass++);
            if (tiled) {  // beyond the book: this frame's tile lists, from this frame's G-buffer
                recordLightCulling(sync.commandBuffer, culling, lightPass, slot, lightView);
                common::timePassEnd(run, sync.commandBuffer, slot, pass++);
            }
            recordLightPass(sync.commandBuffer, lightPass, slot, lightView,
                            tiled ? culling.frames[slot].set : VK_NULL_HANDLE);
            common::timePassEnd(run, sync.commandBuffer, slot, pass++);
        }
        common::recordPostPass(sync.commandBuffer, postPass, target, imageIndex, fxaa, gui.enabled);
        common::timePassEnd(run, sync.commandBuffer, slot, pass++);
        if (gui.enabled) {
            common::recordGuiPass(sync.commandBuffer, guiPass, slot, target, imageIndex, overlay);
            common::timePassEnd(run, sync.commandBuffer, slot, pass++);
        }
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

        if (lastFrame) common::screenshotLastFrame(run, device, target, imageIndex);
        bool current = common::presentTargetImage(target, device, imageIndex);
        common::endFrame(run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget()) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    //< frame-loop
    if (camera.position != scene.camera.position || camera.yaw != scene.camera.yaw ||
        camera.pitch != scene.camera.pitch)
        std::printf("chapter-15: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    camera.position.x, camera.position.y, camera.position.z, camera.yaw, camera.pitch);
    std::vector<std::pair<std::string, std::string>> info =
        common::benchmarkInfo(kChapter, options, device, target);
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(layout->formats))});
    common::reportRun(run, device, info);
    if (gui.enabled)
        std::printf("chapter-15: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    guiPass.growths, guiPass.largestVertices, guiPass.largestIndices);

    if (lightControls.moved) {
        glm::vec3 p =
            lightControls.point >= 0 ? scene.lights[size_t(lightControls.point)].position : glm::vec3(0.0f);
        std::printf("chapter-15: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    lightControls.sunAngle, p.x, p.y, p.z);
    }
    if (tiled) reportLightCulling(culling);
    // Beyond the book: the output read back (beyond/output_dump.cpp).
    if (options.switches.count("check-output")) checkLightOutput(device, lightPass);
    if (options.values.count("dump"))
        dumpFrame(device, lightPass, scenePass, lightView, options.values.at("dump"), !forward);

    //> teardown
    common::destroyRunControl(device, run);
    if (gui.enabled) common::destroyGuiPass(device, guiPass);
    common::destroyGui(gui);
    common::savePipelineCache(device, pipelineCache);
    common::destroyPostPass(device, postPass);
    if (forward) destroyForwardPass(device, forwardPass);
    destroyLightPass(device, lightPass);
    if (tiled) destroyLightCulling(device, culling);
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
