// The frame loop of chapter 15 on (frame_loop.hpp).
#include "common/app/frame_loop.hpp"

#include <cstdio>
#include <exception>

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {

RenderContext openRenderContext(const Options& options, const std::string& chapter, const std::string& title,
                                const DeviceFeatures& features) {
    RenderContext c;
    c.target = openTarget(options, title.c_str());
    c.instance = createInstance(chapter.c_str(), options.validation, targetInstanceExtensions(c.target));
    createTargetSurface(c.target, c.instance);
    c.device = createDevice(c.instance, c.target.surface, options.device, features);
    createTargetImages(c.target, c.device);
    c.framesInFlight = options.framesInFlight;
    c.frames = createFrameSync(c.device, c.framesInFlight);
    c.pipelineCache = loadPipelineCache(c.device, chapter);
    c.gui = createGui(options, c.target);
    if (c.gui.enabled)
        c.guiPass = createGuiPass(c.device, c.pipelineCache.handle, c.target.encodedFormat, c.framesInFlight);
    return c;
}

void startRunControl(RenderContext& c, const Options& options, std::vector<std::string> passes) {
    if (c.gui.enabled) passes.push_back("gui");
    c.run = createRunControl(options, c.device, std::move(passes));
}

void closeRenderContext(RenderContext& c) {
    destroyRunControl(c.device, c.run);
    if (c.gui.enabled) destroyGuiPass(c.device, c.guiPass);
    destroyGui(c.gui);
    savePipelineCache(c.device, c.pipelineCache);
    destroyPipelineCache(c.device, c.pipelineCache);
    destroyFrameSync(c.device, c.frames);
    destroyTargetImages(c.target, c.device);
    destroyDevice(c.device);
    destroyTargetSurface(c.target, c.instance);
    destroyInstance(c.instance);
    closeTarget(c.target);
}

void timedPass(const RenderContext& c, FrameCommands& frame, const std::function<void()>& record) {
    beginPass(c.run, frame.cmd, frame.pass);
    record();
    endPass(c.run, frame.cmd, frame.slot, frame.pass++);
}

//> reload
// Live reload: new pipelines for the passes whose shaders changed are made from the new code
// while the frames in flight still draw with the old ones; then the new ones take their place,
// and the old ones are destroyed once the GPU is done with those frames. If one cannot be made,
// none does: the old pipelines keep drawing, and the error is shown.
void reloadShaders(RenderContext& c, const FrameSteps& steps, const ShaderReload& reload, uint32_t frame) {
    PipelineSwap swap;
    try {
        steps.remakePipelines(reload, swap);
        if (c.gui.enabled)
            remakeGuiPipeline(c.device, c.pipelineCache.handle, c.guiPass, c.target.encodedFormat, reload,
                              swap);
    } catch (const std::exception& e) {
        discardPipelines(c.device, swap);
        finishShaderReload(e.what());
        return;
    }
    swapPipelines(c.device, swap, frame);  // the old ones go once the frames in flight are done
    finishShaderReload();
}
//< reload

// The window changed size: the swapchain, then every image of the window's size. False when the
// window is gone.
bool recreateTarget(RenderContext& c, const FrameSteps& steps) {
    if (!recreateTargetImages(c.target, c.device)) return false;
    steps.resize();
    // The window may have moved to a screen with other formats: what writes the image follows.
    if (c.gui.enabled) retargetGuiPass(c.device, c.pipelineCache.handle, c.guiPass, c.target.encodedFormat);
    return true;
}

//> frame-loop
void runFrameLoop(RenderContext& c, const FrameSteps& steps) {
    // --acquire late: a second command buffer per frame (from the frame's pool) for the passes
    // that write the acquired image.
    std::vector<VkCommandBuffer> lateCommands(steps.acquireLate ? c.frames.size() : 0);
    for (size_t i = 0; i < lateCommands.size(); ++i) {
        VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = c.frames[i].commandPool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(c.device.handle, &allocInfo, &lateCommands[i]));
        nameObject(c.device.handle, lateCommands[i], "frame " + std::to_string(i) + " late commands");
    }
    double lastTime = glfwGetTime();
    for (uint32_t frame = 0;;) {
        bool lastFrame = beginFrame(c.run, c.target, frame);
        if (ShaderReload reload = pollShaderSources()) reloadShaders(c, steps, reload, frame);
        uint32_t slot = frame % c.framesInFlight;
        FrameSync& sync = c.frames[slot];
        ImDrawData* overlay = drawGui(c.gui, c.target, frame, steps.overlay);
        // The book's Engine: input, then update; the keys go to the overlay when it has them.
        if (c.target.window) {
            double now = glfwGetTime();
            steps.input(c.target.window, float(now - lastTime), !guiWantsKeyboard(c.gui),
                        !guiWantsMouse(c.gui));
            lastTime = now;
        }

        // The book's Render.render: wait until this slot's previous frame is done, then acquire
        // the image to present.
        double waitStart = millisecondsSinceStart();
        VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        addFenceWait(c.run.stats, frame, millisecondsSinceStart() - waitStart);
        releaseRetiredPipelines(c.device, frame, c.framesInFlight);
        collectGpuTimes(c.run, c.device, slot);
        uint32_t imageIndex = 0;
        if (!steps.acquireLate) {  // the book's order: the image first
            if (!acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
                if (!recreateTarget(c, steps)) break;
                continue;
            }
            VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));
        }
        if (c.gui.enabled) updateGuiBuffers(c.device, c.guiPass, slot, overlay);

        double updateStart = millisecondsSinceStart();
        steps.update(frame, slot);
        double updateMs = millisecondsSinceStart() - updateStart;

        // The frame's passes into one command buffer, each labelled for graphics debuggers and
        // timed for --benchmark; the overlay last.
        VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
        timeFrameStart(c.run, sync.commandBuffer, slot, frame);
        FrameCommands commands{
            .cmd = sync.commandBuffer, .slot = slot, .frame = frame, .imageIndex = imageIndex};
        double recordStart = millisecondsSinceStart();
        steps.record(commands);
        double recordMs = millisecondsSinceStart() - recordStart;
        if (steps.acquireLate) {
            // The off-screen passes go to the GPU now, with nothing to wait for; the image is
            // acquired only for the passes that write it, recorded into a second command buffer.
            // (Queue order and the passes' barriers still order the two submits.)
            VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
            VkCommandBufferSubmitInfo offscreen{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                                .commandBuffer = sync.commandBuffer};
            VkSubmitInfo2 first{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                                .commandBufferInfoCount = 1,
                                .pCommandBufferInfos = &offscreen};
            VK_CHECK(common::vk13.QueueSubmit2(c.device.queue, 1, &first, VK_NULL_HANDLE));
            if (!acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
                if (!recreateTarget(c, steps)) break;
                continue;
            }
            VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));
            commands.cmd = lateCommands[slot];
            commands.imageIndex = imageIndex;
            VK_CHECK(vkBeginCommandBuffer(commands.cmd, &beginInfo));
        }
        double submitStart = millisecondsSinceStart();
        if (steps.present) steps.present(commands);
        if (c.gui.enabled)
            timedPass(c, commands,
                      [&] { recordGuiPass(commands.cmd, c.guiPass, slot, c.target, imageIndex, overlay); });
        VK_CHECK(vkEndCommandBuffer(commands.cmd));

        // One submit (the second with --acquire late): every colour write of it waits for the
        // acquired image; it signals when done.
        VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                   .semaphore = sync.imageAvailable,
                                   .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = c.target.renderFinished[imageIndex],
                                     .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
        VkCommandBufferSubmitInfo buffer{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                         .commandBuffer = commands.cmd};
        VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = 1,
                             .pWaitSemaphoreInfos = &wait,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &buffer,
                             .signalSemaphoreInfoCount = 1,
                             .pSignalSemaphoreInfos = &signal};
        VK_CHECK(common::vk13.QueueSubmit2(c.device.queue, 1, &submit, sync.inFlight));

        if (lastFrame) screenshotLastFrame(c.run, c.device, c.target, imageIndex);
        bool current = presentTargetImage(c.target, c.device, imageIndex, sync.inFlight);
        addCpuSteps(c.run.stats, frame, updateMs, recordMs, millisecondsSinceStart() - submitStart);
        endFrame(c.run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget(c, steps)) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
}
//< frame-loop

void reportChapterRun(const ChapterInfo& chapter, RenderContext& c,
                      const std::vector<std::pair<std::string, std::string>>& info, const Scene& scene,
                      const Camera& camera, const LightControls& lights) {
    const CameraDesc& start = scene.camera;
    if (camera.position != start.position || camera.yaw != start.yaw || camera.pitch != start.pitch)
        std::printf("%s: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n", chapter.name,
                    camera.position.x, camera.position.y, camera.position.z, camera.yaw, camera.pitch);
    reportRun(c.run, c.device, info);
    if (c.gui.enabled)
        std::printf("%s: GUI buffers grew %u times, to %zu vertices and %zu indices\n", chapter.name,
                    c.guiPass.growths, c.guiPass.largestVertices, c.guiPass.largestIndices);
    if (lights.moved) {
        glm::vec3 p = lights.point >= 0 ? scene.lights[size_t(lights.point)].position : glm::vec3(0.0f);
        std::printf("%s: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    chapter.name, lights.sunAngle, p.x, p.y, p.z);
    }
}

}  // namespace common
