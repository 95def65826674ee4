// chapter-15: deferred rendering II, PBR -- the book's chapter 15 in C++.
//
// chapter-14's frame with a full PBR G-buffer and real lighting:
//   scene pass (scene_pass.cpp): world position, albedo, normal (normal maps through the TBN
//     matrix) and AO/roughness/metallic into four R16G16B16A16_SFLOAT attachments, plus depth;
//   light pass (light_pass.cpp): Cook-Torrance shading (shaders/include/pbr.glsl) of every pixel
//     by the scene's directional and point lights, from a scalar-layout storage buffer, plus
//     ambient light, into an R32G32B32A32_SFLOAT image;
//   post pass (common/passes/post_pass.cpp): into the presentation image, FXAA optional;
//   GUI pass (common/passes/gui_pass.cpp, --gui): the Dear ImGui overlay over it, as the book's GuiRender.
// run() at the end of this file is the chapter in four steps: set up, the frame loop, the report,
// tear down.
#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/gui_pass.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"
#include "gbuffer_layout.hpp"
#include "gpu_types.hpp"
#include "light_pass.hpp"
#include "scene_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-15",
    "deferred rendering II: PBR G-buffer, normal maps, lights (the book's chapter 15)",
    {"final", "position", "albedo", "normal", "pbr", "depth"},  // the order of shade_pixel.glsl's `view`
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {common::kGuiClickChoice, common::kGuiScaleChoice, common::kPipelinesChoice},
};

//> overlay
// The overlay (--gui): the timings window with the view selector (common/app/gui.cpp) and FXAA; a
// second window with the book's light controls and the ambient light.
void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa,
                    common::LightControls& controls, common::Scene& scene, common::GpuScene& gpuScene) {
    common::guiTimingsWindow(
        gui, run, kChapter.views, view,
        {"V  cycles the views", "F  toggles FXAA", common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    ImGui::End();

    common::beginLightsWindow(controls, scene, gpuScene);
    common::endLightsWindow();
}
//< overlay

//> chapter-state
// Everything the chapter makes, in the order setUp() makes it (tearDown() destroys it in
// reverse), and what the frames change.
struct Chapter {
    common::Scene scene;
    common::Target target;
    common::Instance instance;
    common::Device device;
    std::vector<common::FrameSync> frames;
    common::GpuScene gpuScene;
    common::PipelineCache pipelineCache;
    ScenePass scenePass;
    LightPass lightPass;
    common::PostPass postPass;
    common::Gui gui;  // --gui: Dear ImGui's context and input (common/app/gui.cpp) and its pass
    common::GuiPass guiPass;
    common::RunControl run;  // --frames, --resize, --benchmark (each pass timed), --screenshot
    // What the frames change.
    common::Camera camera;
    common::CameraInput cameraInput;
    common::LightControls lightControls;
    LightView lightView;
    bool fxaa = false;
    bool genericPipelines = false;  // --pipelines generic
    double passesMs = 0.0;          // how long createPasses took at start-up (pipelines, mostly)
};
//< chapter-state

//> passes
// The passes, in the order a frame records them.
void createPasses(Chapter& c, uint32_t framesInFlight) {
    // Pipelines made for this scene: one per material class its materials have, and the light
    // pass's for its lights of each kind (unless --pipelines generic).
    c.scenePass = createScenePass(c.device, c.pipelineCache.handle, c.target.extent, c.gpuScene,
                                  framesInFlight, kBookGBuffer, {}, c.genericPipelines);
    c.lightPass =
        createLightPass(c.device, c.pipelineCache.handle, c.target.extent, c.scenePass.gbuffer,
                        framesInFlight, uint32_t(c.scene.lights.size()),
                        {.kinds = c.genericPipelines ? LightKinds{} : lightKinds(shaderLights(c.scene))});
    c.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, c.lightPass.output);
    if (c.gui.enabled)
        c.guiPass =
            common::createGuiPass(c.device, c.pipelineCache.handle, c.target.encodedFormat, framesInFlight);
}

void destroyPasses(Chapter& c) {
    if (c.gui.enabled) common::destroyGuiPass(c.device, c.guiPass);
    common::destroyPostPass(c.device, c.postPass);
    destroyLightPass(c.device, c.lightPass);
    destroyScenePass(c.device, c.scenePass);
}

// Live reload (common/shaders/shader_watch.hpp): edited shaders compiled and checked. New pipelines for
// the passes that use them are made from the new code while the frames in flight still draw
// with the old ones; then the new ones take their place, and the old ones are destroyed once
// the GPU is done with those frames. If one cannot be made, none does: the old pipelines keep
// drawing, and the error is shown.
void reloadShaders(Chapter& c, const common::ShaderReload& reload, uint32_t frame) {
    VkPipelineCache cache = c.pipelineCache.handle;
    common::PipelineSwap swap;
    try {
        remakeScenePipelines(c.device, cache, c.scenePass.pipelines, reload, swap);
        common::remakeFullscreenPipeline(c.device, cache, c.lightPass.pipeline, reload, swap);
        common::remakePostPipelines(c.device, cache, c.postPass, reload, swap);
        if (c.gui.enabled)
            common::remakeGuiPipeline(c.device, cache, c.guiPass, c.target.encodedFormat, reload, swap);
    } catch (const std::exception& e) {
        common::discardPipelines(c.device, swap);
        common::finishShaderReload(e.what());
        return;
    }
    common::swapPipelines(c.device, swap, frame);  // the old ones go once the frames in flight are done
    common::finishShaderReload();
}
//< passes

//> setup
void setUp(Chapter& c, const common::Options& options) {
    common::ModelCache models;
    c.scene = common::sceneFromOptions(options, models);

    c.target = common::openTarget(options, "chapter-15: deferred rendering II, PBR");
    c.instance =
        common::createInstance("chapter-15", options.validation, common::targetInstanceExtensions(c.target));
    common::createTargetSurface(c.target, c.instance);
    // scalarBlockLayout: the feature this chapter adds -- the lights and the scene info are read
    // with the C-like scalar layout (gpu_types.hpp).
    c.device =
        common::createDevice(c.instance, c.target.surface, options.device,
                             {.dynamicRendering = true, .synchronization2 = true, .scalarBlockLayout = true});
    common::createTargetImages(c.target, c.device);
    c.frames = common::createFrameSync(c.device, options.framesInFlight);

    // What the first frame may cost to rasterise, refused beyond a budget (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(c.scene, c.target.extent.width, c.target.extent.height);
    common::checkFrameCost(c.scene, models, {&firstView, 1});
    c.gpuScene = common::loadGpuScene(c.device, c.scene, models,
                                      {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true});
    // The book's G-buffer keeps world positions in 16-bit floats: a scene within +-65504.
    common::checkPositionRange(kBookGBuffer.formats, c.gpuScene.boundsMin, c.gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-15: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                c.gpuScene.draws.size(), static_cast<unsigned long long>(c.gpuScene.triangles),
                c.gpuScene.textures.size(), c.gpuScene.materials.size(), c.scene.lights.size());

    c.pipelineCache = common::loadPipelineCache(c.device, "chapter-15");
    c.gui = common::createGui(options, c.target);
    c.genericPipelines = common::genericPipelines(options);
    double passesStart = common::millisecondsSinceStart();
    createPasses(c, options.framesInFlight);
    c.passesMs = common::millisecondsSinceStart() - passesStart;
    std::vector<std::string> passes{"scene", "light", "post"};
    if (c.gui.enabled) passes.push_back("gui");
    c.run = common::createRunControl(options, c.device, passes);

    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.lightControls = common::findControlledLights(c.scene);
    c.lightView = {.boundsMin = glm::vec4(c.gpuScene.boundsMin, 0.0f),
                   .boundsMax = glm::vec4(c.gpuScene.boundsMax, 0.0f),
                   .view = int(options.view),
                   .near = c.scene.camera.near,
                   .far = c.scene.camera.far};
    c.fxaa = options.switches.count("fxaa") != 0;
}
//< setup

//> resize
// The window changed size: the swapchain, then every image of the window's size.
bool recreateTarget(Chapter& c) {
    if (!common::recreateTargetImages(c.target, c.device)) return false;
    resizeScenePass(c.device, c.scenePass, c.target.extent);
    resizeLightPass(c.device, c.lightPass, c.target.extent, c.scenePass.gbuffer);
    common::resizePostPass(c.device, c.postPass, c.lightPass.output);
    // The window may have moved to a screen with other formats: what writes the image follows.
    common::retargetPostPass(c.device, c.pipelineCache.handle, c.postPass, c.target.format);
    if (c.gui.enabled)
        common::retargetGuiPass(c.device, c.pipelineCache.handle, c.guiPass, c.target.encodedFormat);
    return true;
}
//< resize

// The keys (unless the overlay has them): the camera, the lights; V cycles the views, F toggles FXAA.
void handleInput(Chapter& c, double& lastTime, common::KeyPress& viewKey, common::KeyPress& fxaaKey) {
    if (!c.target.window) return;
    bool keys = !common::guiWantsKeyboard(c.gui), mouse = !common::guiWantsMouse(c.gui);
    double now = glfwGetTime();
    float seconds = float(now - lastTime);
    lastTime = now;
    float sceneSize = glm::length(c.gpuScene.boundsMax - c.gpuScene.boundsMin);
    common::moveCamera(c.target.window, c.camera, c.cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
    if (keys)
        common::moveLights(c.target.window, c.lightControls, c.scene, c.gpuScene, seconds, sceneSize * 0.05f);
    if (common::pressedOnce(c.target.window, viewKey) && keys)
        c.lightView.view = (c.lightView.view + 1) % int(kChapter.views.size());
    if (common::pressedOnce(c.target.window, fxaaKey) && keys) c.fxaa = !c.fxaa;
}

//> update-frame
// This frame's uniforms: the camera, the lights (they may have moved), the scene info.
void updateFrame(Chapter& c, uint32_t slot) {
    glm::mat4 view = common::viewMatrix(c.camera);
    glm::mat4 projection = common::projectionMatrix(c.scene.camera.fov, c.target.extent, c.scene.camera.near,
                                                    c.scene.camera.far);
    setCamera(c.scenePass, slot, projection, view);
    updateLights(c.lightPass, slot, shaderLights(c.scene),
                 {c.camera.position, c.scene.ambientIntensity, c.scene.ambientColor, 0u});
}
//< update-frame

//> record-frame
// The frame's passes into one command buffer, each labelled for graphics debuggers and timed for
// --benchmark.
void recordFrame(Chapter& c, common::FrameSync& sync, uint32_t slot, uint32_t frame, uint32_t imageIndex,
                 ImDrawData* overlay) {
    VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
    VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
    common::timeFrameStart(c.run, sync.commandBuffer, slot, frame);
    common::beginPass(c.run, sync.commandBuffer, 0);
    recordScenePass(sync.commandBuffer, c.scenePass, c.gpuScene, slot, c.camera.position);
    common::endPass(c.run, sync.commandBuffer, slot, 0);
    common::beginPass(c.run, sync.commandBuffer, 1);
    recordLightPass(sync.commandBuffer, c.lightPass, slot, c.lightView);
    common::endPass(c.run, sync.commandBuffer, slot, 1);
    common::beginPass(c.run, sync.commandBuffer, 2);
    common::recordPostPass(sync.commandBuffer, c.postPass, c.target, imageIndex, c.fxaa, c.gui.enabled);
    common::endPass(c.run, sync.commandBuffer, slot, 2);
    if (c.gui.enabled) {
        common::beginPass(c.run, sync.commandBuffer, 3);
        common::recordGuiPass(sync.commandBuffer, c.guiPass, slot, c.target, imageIndex, overlay);
        common::endPass(c.run, sync.commandBuffer, slot, 3);
    }
    VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
}
//< record-frame

//> frame-loop
void frameLoop(Chapter& c, const common::Options& options) {
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(c.run, c.target, frame);
        if (common::ShaderReload reload = common::pollShaderSources()) reloadShaders(c, reload, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = c.frames[slot];
        ImDrawData* overlay = common::drawGui(c.gui, c.target, frame, [&] {
            overlayWidgets(c.gui, c.run, &c.lightView.view, &c.fxaa, c.lightControls, c.scene, c.gpuScene);
        });
        handleInput(c, lastTime, viewKey, fxaaKey);

        // Wait until this slot's previous frame is done, then acquire the image to present.
        VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::releaseRetiredPipelines(c.device, frame, options.framesInFlight);
        common::collectGpuTimes(c.run, c.device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget(c)) break;
            continue;
        }
        VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));
        if (c.gui.enabled) common::updateGuiBuffers(c.device, c.guiPass, slot, overlay);

        updateFrame(c, slot);
        recordFrame(c, sync, slot, frame, imageIndex, overlay);

        // One submit: wait for the acquired image before writing colour, signal when done.
        VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                   .semaphore = sync.imageAvailable,
                                   .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = c.target.renderFinished[imageIndex],
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
        VK_CHECK(common::vk13.QueueSubmit2(c.device.queue, 1, &submit, sync.inFlight));

        if (lastFrame) common::screenshotLastFrame(c.run, c.device, c.target, imageIndex);
        bool current = common::presentTargetImage(c.target, c.device, imageIndex, sync.inFlight);
        common::endFrame(c.run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget(c)) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
}
//< frame-loop

// After the last frame: where the camera and lights went, --benchmark's report, --check-output.
void report(Chapter& c, const common::Options& options) {
    const common::CameraDesc& start = c.scene.camera;
    if (c.camera.position != start.position || c.camera.yaw != start.yaw || c.camera.pitch != start.pitch)
        std::printf("chapter-15: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    c.camera.position.x, c.camera.position.y, c.camera.position.z, c.camera.yaw,
                    c.camera.pitch);
    std::vector<std::pair<std::string, std::string>> info =
        common::benchmarkInfo(kChapter, options, c.device, c.target, c.scenePass.formats.depth);
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(kBookGBuffer.formats))});
    common::addPipelineInfo(info, c.scenePass.pipelines.pipelines.size(), c.passesMs);
    info.push_back({"light_pipeline", describeLightKinds(c.lightPass.kinds)});
    common::reportRun(c.run, c.device, info);
    if (c.gui.enabled)
        std::printf("chapter-15: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    c.guiPass.growths, c.guiPass.largestVertices, c.guiPass.largestIndices);
    if (c.lightControls.moved) {
        glm::vec3 p = c.lightControls.point >= 0 ? c.scene.lights[size_t(c.lightControls.point)].position
                                                 : glm::vec3(0.0f);
        std::printf("chapter-15: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    c.lightControls.sunAngle, p.x, p.y, p.z);
    }
    if (options.switches.count("check-output")) checkLightOutput(c.device, c.lightPass);
}

//> teardown
void tearDown(Chapter& c) {
    common::destroyRunControl(c.device, c.run);
    destroyPasses(c);
    common::destroyGui(c.gui);
    common::savePipelineCache(c.device, c.pipelineCache);
    common::destroyPipelineCache(c.device, c.pipelineCache);
    common::destroyGpuScene(c.device, c.gpuScene);
    common::destroyFrameSync(c.device, c.frames);
    common::destroyTargetImages(c.target, c.device);
    common::destroyDevice(c.device);
    common::destroyTargetSurface(c.target, c.instance);
    common::destroyInstance(c.instance);
    common::closeTarget(c.target);
}
//< teardown

//> run
void run(const common::Options& options) {
    Chapter chapter;
    setUp(chapter, options);
    frameLoop(chapter, options);
    report(chapter, options);
    tearDown(chapter);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
