// chapter-10: deferred shading with render passes -- the book's chapter 10 in C++.
//
// The frame is split in two passes, each with its own VkRenderPass and framebuffer, recorded
// into their own command buffers and submitted separately, joined by a semaphore:
//   geometry pass (geometry_pass.cpp): the scene into a G-buffer of albedo + depth;
//   lighting pass (lighting_pass.cpp): a full-screen triangle into the target image, reading the
//   G-buffer. There is no lighting yet -- it copies albedo, as the book does -- until chapter-15.
// Models, textures, the scene file and the camera (the book's chapters 7-9) come from common/.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"
#include "geometry_pass.hpp"
#include "lighting_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-10",
    "deferred shading with render passes (the book's chapter 10)",
    {"final", "albedo", "depth"},  // --view names; their order is the lighting shader's `view`
    {},
    {common::kPipelinesChoice},
};

// What one frame in flight owns: common::FrameSync (its fence, the image-available semaphore, a
// command buffer), plus the geometry pass's own command buffer and the semaphore that tells the
// lighting submission the G-buffer is written.
struct Frame {
    common::FrameSync sync;
    VkCommandPool geometryPool = VK_NULL_HANDLE;
    VkCommandBuffer geometryCommands = VK_NULL_HANDLE;
    VkSemaphore geometryComplete = VK_NULL_HANDLE;
};

std::vector<Frame> createFrames(const common::Device& device, uint32_t framesInFlight) {
    std::vector<Frame> frames;
    for (common::FrameSync& sync : common::createFrameSync(device, framesInFlight)) {
        Frame frame{.sync = sync};
        VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                         .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                         .queueFamilyIndex = device.queueFamily};
        VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &frame.geometryPool));
        common::nameObject(device.handle, frame.geometryPool, "geometry commands");
        VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = frame.geometryPool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &frame.geometryCommands));
        frame.geometryComplete = common::createSemaphore(device);
        common::nameObject(device.handle, frame.geometryCommands, "geometry commands");
        common::nameObject(device.handle, frame.geometryComplete, "geometry complete");
        frames.push_back(frame);
    }
    return frames;
}

void destroyFrames(const common::Device& device, std::vector<Frame>& frames) {
    std::vector<common::FrameSync> syncs;
    for (Frame& frame : frames) {
        vkDestroySemaphore(device.handle, frame.geometryComplete, nullptr);
        vkDestroyCommandPool(device.handle, frame.geometryPool, nullptr);  // frees its command buffer
        syncs.push_back(frame.sync);
    }
    common::destroyFrameSync(device, syncs);
    frames.clear();
}

//> chapter-state
// Everything the chapter makes, in the order setUp() makes it (tearDown() destroys it in
// reverse), and what the frames change.
struct Chapter {
    common::Scene scene;
    common::Target target;
    common::Instance instance;
    common::Device device;
    std::vector<Frame> frames;
    common::GpuScene gpuScene;
    common::PipelineCache pipelineCache;
    GeometryPass geometryPass;
    LightingPass lightingPass;
    // --benchmark: timestamps at the start, after the geometry pass, after the lighting pass. The
    // lighting command buffers are pre-recorded per image, so the last timestamp goes into the
    // frame slot's own small command buffer, submitted right after the lighting one.
    common::RunControl run;
    // The fence of the frame that last submitted each image's lighting command buffer.
    std::vector<VkFence> imageInFlight;
    // What the frames change.
    common::Camera camera;
    common::CameraInput cameraInput;
    LightingView lightingView;
    bool genericPipelines = false;  // --pipelines generic
    double passesMs = 0.0;          // how long createPasses took at start-up (pipelines, mostly)
};
//< chapter-state

//> passes
// The two passes. The lighting pass's command buffers are recorded once here, the geometry pass's
// every frame.
void createPasses(Chapter& c, uint32_t framesInFlight) {
    c.geometryPass = createGeometryPass(c.device, c.pipelineCache.handle, c.target.extent, c.gpuScene,
                                        framesInFlight, c.genericPipelines);
    c.lightingPass = createLightingPass(c.device, c.pipelineCache.handle, c.target, c.geometryPass.gbuffer);
    recordLightingPass(c.device, c.lightingPass, c.target, c.lightingView);
    setProjection(c.geometryPass, common::projectionMatrix(c.scene.camera.fov, c.target.extent,
                                                           c.scene.camera.near, c.scene.camera.far));
}

void destroyPasses(Chapter& c) {
    destroyLightingPass(c.device, c.lightingPass);
    destroyGeometryPass(c.device, c.geometryPass);
}

// Live reload (common/shaders/shader_watch.hpp): edited shaders compiled and checked. New pipelines for
// the passes that use them are made from the new code while the frames in flight still draw
// with the old ones; then the new ones take their place (the old ones are destroyed once the
// GPU is done with those frames), and the lighting command buffers, which name the pipeline, are
// recorded again. If one cannot be made, none does: the old pipelines keep drawing, and the
// error is shown.
void reloadShaders(Chapter& c, const common::ShaderReload& reload, uint32_t frame) {
    VkPipelineCache cache = c.pipelineCache.handle;
    common::PipelineSwap swap;
    bool lighting = false;
    try {
        remakeGeometryPipeline(c.device, cache, c.geometryPass, reload, swap);
        lighting = remakeLightingPipeline(c.device, cache, c.lightingPass, c.target, reload, swap);
    } catch (const std::exception& e) {
        common::discardPipelines(c.device, swap);
        common::finishShaderReload(e.what());
        return;
    }
    common::swapPipelines(c.device, swap, frame);  // the old ones go once the frames in flight are done
    if (lighting) {  // its command buffers, which name the pipeline, recorded again once not in use
        VK_CHECK(vkDeviceWaitIdle(c.device.handle));
        recordLightingPass(c.device, c.lightingPass, c.target, c.lightingView);
    }
    common::finishShaderReload();
}
//< passes

//> setup
void setUp(Chapter& c, const common::Options& options) {
    // The scene is read before any Vulkan object exists: a bad file fails fast with exit code 2.
    common::ModelCache models;
    c.scene = common::sceneFromOptions(options, models);

    c.target = common::openTarget(options, "chapter-10: deferred shading with render passes");
    c.instance =
        common::createInstance("chapter-10", options.validation, common::targetInstanceExtensions(c.target));
    common::createTargetSurface(c.target, c.instance);
    c.device = common::createDevice(c.instance, c.target.surface, options.device);
    common::createTargetImages(c.target, c.device);
    c.frames = createFrames(c.device, options.framesInFlight);

    // What the first frame may cost to rasterise, refused beyond a budget (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(c.scene, c.target.extent.width, c.target.extent.height);
    common::checkFrameCost(c.scene, models, {&firstView, 1});
    c.gpuScene = common::loadGpuScene(c.device, c.scene, models, {});  // the CPU copies go with `models`
    std::printf("chapter-10: %zu draws, %llu triangles, %zu textures, %zu materials\n",
                c.gpuScene.draws.size(), static_cast<unsigned long long>(c.gpuScene.triangles),
                c.gpuScene.textures.size(), c.gpuScene.materials.size());

    c.pipelineCache = common::loadPipelineCache(c.device, "chapter-10");
    c.lightingView = {int(options.view), c.scene.camera.near, c.scene.camera.far};
    c.genericPipelines = common::genericPipelines(options);
    double passesStart = common::millisecondsSinceStart();
    createPasses(c, options.framesInFlight);
    c.passesMs = common::millisecondsSinceStart() - passesStart;
    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.run = common::createRunControl(options, c.device, {"geometry", "lighting"});
    c.imageInFlight.assign(c.target.images.size(), VK_NULL_HANDLE);
}
//< setup

//> resize
// A new target size: new G-buffer attachments and geometry framebuffer, new lighting
// framebuffers and descriptors, a new projection, and the lighting command buffers
// recorded again. Render passes and pipelines stay, unless the target's format changed (the
// lighting pass's, which write the target).
bool recreateTarget(Chapter& c) {
    if (!common::recreateTargetImages(c.target, c.device)) return false;  // waits for the device
    resizeGeometryPass(c.device, c.geometryPass, c.target.extent);
    resizeLightingPass(c.device, c.pipelineCache.handle, c.lightingPass, c.target, c.geometryPass.gbuffer);
    recordLightingPass(c.device, c.lightingPass, c.target, c.lightingView);
    setProjection(c.geometryPass, common::projectionMatrix(c.scene.camera.fov, c.target.extent,
                                                           c.scene.camera.near, c.scene.camera.far));
    c.imageInFlight.assign(c.target.images.size(), VK_NULL_HANDLE);
    return true;
}
//< resize

//> frame-loop
void frameLoop(Chapter& c, const common::Options& options) {
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V};
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(c.run, c.target, frame);
        if (common::ShaderReload reload = common::pollShaderSources()) reloadShaders(c, reload, frame);
        uint32_t slot = frame % options.framesInFlight;
        Frame& inFlight = c.frames[slot];
        common::FrameSync& sync = inFlight.sync;

        if (c.target.window) {  // camera controls, and V cycles through the --view attachments
            double now = glfwGetTime();
            float speed = glm::length(c.gpuScene.boundsMax - c.gpuScene.boundsMin) * 0.15f;
            common::moveCamera(c.target.window, c.camera, c.cameraInput, float(now - lastTime), speed);
            lastTime = now;
            if (common::pressedOnce(c.target.window, viewKey)) {
                c.lightingView.view = (c.lightingView.view + 1) % int(kChapter.views.size());
                VK_CHECK(vkDeviceWaitIdle(c.device.handle));  // the lighting command buffers are re-recorded
                recordLightingPass(c.device, c.lightingPass, c.target, c.lightingView);
            }
        }

        VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::releaseRetiredPipelines(c.device, frame, options.framesInFlight);
        common::collectGpuTimes(c.run, c.device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget(c)) break;
            continue;
        }
        // The lighting command buffer of this image is reused as recorded: the frame that last
        // submitted it must be finished (it may have used the other frame-in-flight slot).
        if (c.imageInFlight[imageIndex] != VK_NULL_HANDLE && c.imageInFlight[imageIndex] != sync.inFlight)
            VK_CHECK(vkWaitForFences(c.device.handle, 1, &c.imageInFlight[imageIndex], VK_TRUE, UINT64_MAX));
        c.imageInFlight[imageIndex] = sync.inFlight;
        VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));

        // Geometry pass: recorded every frame (the camera moves), submitted on its own, and it
        // signals geometryComplete. It does not touch the target image, so it does not wait for it.
        setView(c.geometryPass, slot, common::viewMatrix(c.camera));
        VK_CHECK(vkResetCommandPool(c.device.handle, inFlight.geometryPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(inFlight.geometryCommands, &beginInfo));
        common::timeFrameStart(c.run, inFlight.geometryCommands, slot, frame);
        common::beginPass(c.run, inFlight.geometryCommands, 0);
        recordGeometryPass(inFlight.geometryCommands, c.geometryPass, c.gpuScene, slot);
        common::endPass(c.run, inFlight.geometryCommands, slot, 0);
        VK_CHECK(vkEndCommandBuffer(inFlight.geometryCommands));
        VkSubmitInfo geometrySubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .commandBufferCount = 1,
            .pCommandBuffers = &inFlight.geometryCommands,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &inFlight.geometryComplete,
        };
        VK_CHECK(vkQueueSubmit(c.device.queue, 1, &geometrySubmit, VK_NULL_HANDLE));

        // Lighting pass: its pre-recorded command buffer for this image. It waits for the
        // G-buffer where it first reads it (the fragment shader) and for the image where it
        // first writes it (colour output); it signals the image's renderFinished and the
        // frame's fence, which therefore also covers the geometry submission before it.
        VkSemaphore waits[] = {inFlight.geometryComplete, sync.imageAvailable};
        VkPipelineStageFlags waitStages[] = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                                             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkCommandBuffer lighting[] = {c.lightingPass.commandBuffers[imageIndex], sync.commandBuffer};
        if (c.run.benchmark) {
            VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
            VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
            common::timePassEnd(c.run, sync.commandBuffer, slot, 1);
            VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
        }
        VkSubmitInfo lightingSubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .waitSemaphoreCount = 2,
            .pWaitSemaphores = waits,
            .pWaitDstStageMask = waitStages,
            .commandBufferCount = c.run.benchmark ? 2u : 1u,
            .pCommandBuffers = lighting,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &c.target.renderFinished[imageIndex],
        };
        VK_CHECK(vkQueueSubmit(c.device.queue, 1, &lightingSubmit, sync.inFlight));

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

//> teardown
void tearDown(Chapter& c) {
    common::destroyRunControl(c.device, c.run);
    common::savePipelineCache(c.device, c.pipelineCache);
    destroyPasses(c);
    common::destroyPipelineCache(c.device, c.pipelineCache);
    common::destroyGpuScene(c.device, c.gpuScene);
    destroyFrames(c.device, c.frames);
    common::destroyTargetImages(c.target, c.device);
    common::destroyDevice(c.device);
    common::destroyTargetSurface(c.target, c.instance);
    common::destroyInstance(c.instance);
    common::closeTarget(c.target);
}
//< teardown

//> run
// The chapter in four steps: set up, the frame loop, the report (--benchmark), tear down.
void run(const common::Options& options) {
    Chapter chapter;
    setUp(chapter, options);
    frameLoop(chapter, options);
    std::vector<std::pair<std::string, std::string>> info = common::benchmarkInfo(
        kChapter, options, chapter.device, chapter.target, chapter.geometryPass.depthFormat);
    common::addPipelineInfo(info, chapter.geometryPass.pipelines.size(), chapter.passesMs);
    common::reportRun(chapter.run, chapter.device, info);
    tearDown(chapter);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
