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
//   GUI pass   (common/gui_pass.cpp, --gui): Dear ImGui's overlay drawn over it, as the book's GuiRender.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstdio>
#include <vector>

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
#include "light_pass.hpp"
#include "scene_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-14",
    "deferred rendering with dynamic rendering and synchronization2 (the book's chapter 14)",
    {"final", "albedo", "depth"},
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"}, common::kGuiSwitch},
    {common::kGuiClickChoice},
};

//> overlay
// The overlay's widgets (--gui): the timings window with the view selector (common/gui.cpp), and
// FXAA in the same window.
void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa) {
    common::guiTimingsWindow(gui, run, kChapter.views, view, {"V  cycles the views", "F  toggles FXAA"});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    ImGui::End();
}
//< overlay

void run(const common::Options& options) {
    //> setup
    common::ModelCache models;
    common::Scene scene = common::sceneFromOptions(options, models);

    common::Target target = common::openTarget(options, "chapter-14: deferred rendering, dynamic rendering");
    common::Instance instance =
        common::createInstance("chapter-14", options.validation, common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    // The two Vulkan 1.3 features this chapter is about.
    common::Device device = common::createDevice(instance, target.surface, options.device,
                                                 {.dynamicRendering = true, .synchronization2 = true});
    common::createTargetImages(target, device);
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);

    common::GpuScene gpuScene = common::loadGpuScene(device, scene, models, {});
    models.clear();
    std::printf("chapter-14: %zu draws, %llu triangles, %zu textures, %zu materials\n", gpuScene.draws.size(),
                static_cast<unsigned long long>(gpuScene.triangles), gpuScene.textures.size(),
                gpuScene.materials.size());

    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-14");
    ScenePass scenePass =
        createScenePass(device, pipelineCache.handle, target.extent, gpuScene, options.framesInFlight);
    LightPass lightPass = createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer);
    common::PostPass postPass =
        common::createPostPass(device, pipelineCache.handle, target.format, lightPass.output);

    common::Camera camera{scene.camera.position, scene.camera.yaw, scene.camera.pitch};
    common::CameraInput cameraInput;
    LightView lightView{int(options.view), scene.camera.near, scene.camera.far};
    bool fxaa = options.switches.count("fxaa") != 0;

    // --gui: Dear ImGui's context and input (common/gui.cpp) and the pass that draws it.
    common::Gui gui = common::createGui(options, target);
    common::GuiPass guiPass;
    if (gui.enabled)
        guiPass = common::createGuiPass(device, pipelineCache.handle, target.format, options.framesInFlight);

    // --frames, --resize, --benchmark (each pass timed), --screenshot.
    std::vector<std::string> passes{"scene", "light", "post"};
    if (gui.enabled) passes.push_back("gui");
    common::RunControl run = common::createRunControl(options, device, passes);
    //< setup

    //> resize
    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;  // waits for the device
        resizeScenePass(device, scenePass, target.extent);
        resizeLightPass(device, lightPass, target.extent, scenePass.gbuffer);
        common::resizePostPass(device, postPass, lightPass.output);
        return true;
    };
    //< resize

    //> frame-loop
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(run, target, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];

        ImDrawData* overlay =
            common::drawGui(gui, target, frame, [&] { overlayWidgets(gui, run, &lightView.view, &fxaa); });
        bool keys = !common::guiWantsKeyboard(gui), mouse = !common::guiWantsMouse(gui);
        if (target.window) {  // camera; V cycles the views, F toggles FXAA (unless the GUI has them)
            double now = glfwGetTime();
            float speed = glm::length(gpuScene.boundsMax - gpuScene.boundsMin) * 0.15f;
            common::moveCamera(target.window, camera, cameraInput, float(now - lastTime), speed, keys, mouse);
            lastTime = now;
            if (common::pressedOnce(target.window, viewKey) && keys)
                lightView.view = (lightView.view + 1) % int(kChapter.views.size());
            if (common::pressedOnce(target.window, fxaaKey) && keys) fxaa = !fxaa;
        }

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::collectGpuTimes(run, device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));
        if (gui.enabled) common::updateGuiBuffers(device, guiPass, slot, overlay);

        // One command buffer for the whole frame: three passes (four with --gui), joined by
        // barriers only.
        setCamera(
            scenePass, slot,
            common::projectionMatrix(scene.camera.fov, target.extent, scene.camera.near, scene.camera.far),
            common::viewMatrix(camera));
        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
        common::timeFrameStart(run, sync.commandBuffer, slot, frame);
        recordScenePass(sync.commandBuffer, scenePass, gpuScene, slot);
        common::timePassEnd(run, sync.commandBuffer, slot, 0);
        recordLightPass(sync.commandBuffer, lightPass, lightView);
        common::timePassEnd(run, sync.commandBuffer, slot, 1);
        common::recordPostPass(sync.commandBuffer, postPass, target, imageIndex, fxaa, gui.enabled);
        common::timePassEnd(run, sync.commandBuffer, slot, 2);
        if (gui.enabled) {
            common::recordGuiPass(sync.commandBuffer, guiPass, slot, target, imageIndex, overlay);
            common::timePassEnd(run, sync.commandBuffer, slot, 3);
        }
        VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));

        // synchronization2's submit: each semaphore carries its own stage mask. The image is
        // waited for where it is first written (colour output, the post pass); renderFinished
        // is signalled when everything in the batch is done.
        VkSemaphoreSubmitInfo wait{
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = sync.imageAvailable,
            .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        };
        VkSemaphoreSubmitInfo signal{
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = target.renderFinished[imageIndex],
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
        std::printf("chapter-14: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    camera.position.x, camera.position.y, camera.position.z, camera.yaw, camera.pitch);
    common::reportRun(run, device, common::benchmarkInfo(kChapter, options, device, target));
    if (gui.enabled)
        std::printf("chapter-14: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    guiPass.growths, guiPass.largestVertices, guiPass.largestIndices);

    //> teardown
    common::destroyRunControl(device, run);
    if (gui.enabled) common::destroyGuiPass(device, guiPass);
    common::destroyGui(gui);
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
