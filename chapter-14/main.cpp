// chapter-14: deferred rendering with dynamic rendering and synchronization2 -- the book's
// chapter 14 in C++.
//
// The same deferred split as chapter-10, with the Vulkan 1.3 path: no VkRenderPass and no
// VkFramebuffer; each pass begins with vkCmdBeginRendering and moves its images between layouts
// with VkImageMemoryBarrier2 (renderInit / renderFinish). All three passes go into one command
// buffer per frame, submitted once with vkQueueSubmit2:
//   scene pass (scene_pass.cpp): the scene into the G-buffer (albedo + depth);
//   light pass (light_pass.cpp): a full-screen triangle into an R32G32B32A32_SFLOAT image;
//   post pass  (post_pass.cpp): that image into the presentation image (FXAA optional);
//   GUI pass   (common/passes/gui_pass.cpp, --gui): Dear ImGui's overlay drawn over it, as the book's
//   GuiRender.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/gui.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
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
#include "light_pass.hpp"
#include "scene_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-14",
    "deferred rendering with dynamic rendering and synchronization2 (the book's chapter 14)",
    {"final", "albedo", "depth"},
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {common::kGuiClickChoice, common::kGuiScaleChoice, common::kPipelinesChoice},
};

//> overlay
// The overlay's widgets (--gui): the timings window with the view selector (common/app/gui.cpp), and
// FXAA in the same window.
void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa) {
    common::guiTimingsWindow(gui, run, kChapter.views, view, {"V  cycles the views", "F  toggles FXAA"});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    ImGui::End();
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
    LightView lightView;
    bool fxaa = false;
    bool genericPipelines = false;  // --pipelines generic
    double passesMs = 0.0;          // how long createPasses took at start-up (pipelines, mostly)
};
//< chapter-state

//> passes
// The passes, in the order a frame records them.
void createPasses(Chapter& c, uint32_t framesInFlight) {
    c.scenePass = createScenePass(c.device, c.pipelineCache.handle, c.target.extent, c.gpuScene,
                                  framesInFlight, c.genericPipelines);
    c.lightPass = createLightPass(c.device, c.pipelineCache.handle, c.target.extent, c.scenePass.gbuffer);
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
        remakeScenePipeline(c.device, cache, c.scenePass, reload, swap);
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

    c.target = common::openTarget(options, "chapter-14: deferred rendering, dynamic rendering");
    c.instance =
        common::createInstance("chapter-14", options.validation, common::targetInstanceExtensions(c.target));
    common::createTargetSurface(c.target, c.instance);
    // The two Vulkan 1.3 features this chapter is about: core on a 1.3 device, extensions
    // (VK_KHR_dynamic_rendering, VK_KHR_synchronization2) on a 1.2 one; common::vk13 holds their
    // commands under whichever names the device has.
    c.device = common::createDevice(c.instance, c.target.surface, options.device,
                                    {.dynamicRendering = true, .synchronization2 = true});
    common::createTargetImages(c.target, c.device);
    c.frames = common::createFrameSync(c.device, options.framesInFlight);

    // What the first frame may cost to rasterise, refused beyond a budget (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(c.scene, c.target.extent.width, c.target.extent.height);
    common::checkFrameCost(c.scene, models, {&firstView, 1});
    c.gpuScene = common::loadGpuScene(c.device, c.scene, models, {});
    std::printf("chapter-14: %zu draws, %llu triangles, %zu textures, %zu materials\n",
                c.gpuScene.draws.size(), static_cast<unsigned long long>(c.gpuScene.triangles),
                c.gpuScene.textures.size(), c.gpuScene.materials.size());

    c.pipelineCache = common::loadPipelineCache(c.device, "chapter-14");
    c.gui = common::createGui(options, c.target);
    c.genericPipelines = common::genericPipelines(options);
    double passesStart = common::millisecondsSinceStart();
    createPasses(c, options.framesInFlight);
    c.passesMs = common::millisecondsSinceStart() - passesStart;
    std::vector<std::string> passes{"scene", "light", "post"};
    if (c.gui.enabled) passes.push_back("gui");
    c.run = common::createRunControl(options, c.device, passes);

    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.lightView = {int(options.view), c.scene.camera.near, c.scene.camera.far};
    c.fxaa = options.switches.count("fxaa") != 0;
}
//< setup

//> resize
bool recreateTarget(Chapter& c) {
    if (!common::recreateTargetImages(c.target, c.device)) return false;  // waits for the device
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

// The keys (unless the overlay has them): the camera; V cycles the views, F toggles FXAA.
void handleInput(Chapter& c, double& lastTime, common::KeyPress& viewKey, common::KeyPress& fxaaKey) {
    if (!c.target.window) return;
    bool keys = !common::guiWantsKeyboard(c.gui), mouse = !common::guiWantsMouse(c.gui);
    double now = glfwGetTime();
    float speed = glm::length(c.gpuScene.boundsMax - c.gpuScene.boundsMin) * 0.15f;
    common::moveCamera(c.target.window, c.camera, c.cameraInput, float(now - lastTime), speed, keys, mouse);
    lastTime = now;
    if (common::pressedOnce(c.target.window, viewKey) && keys)
        c.lightView.view = (c.lightView.view + 1) % int(kChapter.views.size());
    if (common::pressedOnce(c.target.window, fxaaKey) && keys) c.fxaa = !c.fxaa;
}

//> record-frame
// One command buffer for the whole frame: three passes (four with --gui), joined by barriers
// only, each labelled for graphics debuggers and timed for --benchmark.
void recordFrame(Chapter& c, common::FrameSync& sync, uint32_t slot, uint32_t frame, uint32_t imageIndex,
                 ImDrawData* overlay) {
    setCamera(c.scenePass, slot,
              common::projectionMatrix(c.scene.camera.fov, c.target.extent, c.scene.camera.near,
                                       c.scene.camera.far),
              common::viewMatrix(c.camera));
    VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
    VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
    common::timeFrameStart(c.run, sync.commandBuffer, slot, frame);
    common::beginPass(c.run, sync.commandBuffer, 0);
    recordScenePass(sync.commandBuffer, c.scenePass, c.gpuScene, slot);
    common::endPass(c.run, sync.commandBuffer, slot, 0);
    common::beginPass(c.run, sync.commandBuffer, 1);
    recordLightPass(sync.commandBuffer, c.lightPass, c.lightView);
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
        ImDrawData* overlay = common::drawGui(
            c.gui, c.target, frame, [&] { overlayWidgets(c.gui, c.run, &c.lightView.view, &c.fxaa); });
        handleInput(c, lastTime, viewKey, fxaaKey);

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

        recordFrame(c, sync, slot, frame, imageIndex, overlay);

        // synchronization2's submit: each semaphore carries its own stage mask. The image is
        // waited for at colour output, the stage that writes it -- but a wait holds that stage for
        // every command of the batch, so the scene pass's G-buffer writes and the light pass's
        // output wait for the image too; only the work before colour output (vertex and fragment
        // shading, the depth tests) may start earlier. This is the book's frame; chapter-15-lab's
        // --acquire late submits the off-screen passes before acquiring. renderFinished is
        // signalled when everything in the batch is done.
        VkSemaphoreSubmitInfo wait{
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = sync.imageAvailable,
            .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        };
        VkSemaphoreSubmitInfo signal{
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = c.target.renderFinished[imageIndex],
            .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
        };
        VkCommandBufferSubmitInfo commands{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
            .commandBuffer = sync.commandBuffer,
        };
        VkSubmitInfo2 submit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
            .waitSemaphoreInfoCount = 1,
            .pWaitSemaphoreInfos = &wait,
            .commandBufferInfoCount = 1,
            .pCommandBufferInfos = &commands,
            .signalSemaphoreInfoCount = 1,
            .pSignalSemaphoreInfos = &signal,
        };
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

// After the last frame: where the camera went, the --benchmark report, the GUI buffers' growth.
void report(Chapter& c, const common::Options& options) {
    const common::CameraDesc& start = c.scene.camera;
    if (c.camera.position != start.position || c.camera.yaw != start.yaw || c.camera.pitch != start.pitch)
        std::printf("chapter-14: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    c.camera.position.x, c.camera.position.y, c.camera.position.z, c.camera.yaw,
                    c.camera.pitch);
    std::vector<std::pair<std::string, std::string>> info =
        common::benchmarkInfo(kChapter, options, c.device, c.target, c.scenePass.gbuffer.depth.format);
    common::addPipelineInfo(info, c.scenePass.pipelines.size(), c.passesMs);
    common::reportRun(c.run, c.device, info);
    if (c.gui.enabled)
        std::printf("chapter-14: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    c.guiPass.growths, c.guiPass.largestVertices, c.guiPass.largestIndices);
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
// The chapter in four steps: set up, the frame loop, the report, tear down.
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
