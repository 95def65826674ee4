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

#include "common/benchmark.hpp"
#include "common/camera.hpp"
#include "common/check.hpp"
#include "common/cli.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/gpu_scene.hpp"
#include "common/instance.hpp"
#include "common/pipeline.hpp"
#include "common/run_control.hpp"
#include "common/scene.hpp"
#include "common/target.hpp"
#include "geometry_pass.hpp"
#include "lighting_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-10",
    "deferred shading with render passes (the book's chapter 10)",
    {"final", "albedo", "depth"},  // --view names; their order is the lighting shader's `view`
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
        VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = frame.geometryPool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &frame.geometryCommands));
        frame.geometryComplete = common::createSemaphore(device);
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

void run(const common::Options& options) {
    //> setup
    // The scene is read before any Vulkan object exists: a bad file fails fast with exit code 2.
    common::ModelCache models;
    common::Scene scene = common::sceneFromOptions(options, models);

    common::Target target = common::openTarget(options, "chapter-10: deferred shading with render passes");
    common::Instance instance =
        common::createInstance("chapter-10", options.validation, common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    common::Device device = common::createDevice(instance, target.surface, options.device);
    common::createTargetImages(target, device);
    std::vector<Frame> frames = createFrames(device, options.framesInFlight);

    common::GpuScene gpuScene = common::loadGpuScene(device, scene, models, {});
    models.clear();  // the CPU copies are on the GPU now
    std::printf("chapter-10: %zu draws, %llu triangles, %zu textures, %zu materials\n", gpuScene.draws.size(),
                static_cast<unsigned long long>(gpuScene.triangles), gpuScene.textures.size(),
                gpuScene.materials.size());

    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-10");
    GeometryPass geometryPass =
        createGeometryPass(device, pipelineCache.handle, target.extent, gpuScene, options.framesInFlight);
    LightingPass lightingPass =
        createLightingPass(device, pipelineCache.handle, target, geometryPass.gbuffer);
    LightingView lightingView{int(options.view), scene.camera.near, scene.camera.far};
    recordLightingPass(device, lightingPass, target, lightingView);

    common::Camera camera{scene.camera.position, scene.camera.yaw, scene.camera.pitch};
    common::CameraInput cameraInput;
    setProjection(geometryPass, common::projectionMatrix(scene.camera.fov, target.extent, scene.camera.near,
                                                         scene.camera.far));

    // --benchmark: timestamps at the start, after the geometry pass, after the lighting pass. The
    // lighting command buffers are pre-recorded per image, so the last timestamp goes into the frame
    // slot's own small command buffer, submitted right after the lighting one.
    common::RunControl run = common::createRunControl(options, device, {"geometry", "lighting"});
    //< setup

    //> resize
    // A new target size: new G-buffer attachments and geometry framebuffer, new lighting
    // framebuffers and descriptors, a new projection, and the lighting command buffers
    // recorded again. Render passes and pipelines stay.
    std::vector<VkFence> imageInFlight(target.images.size(), VK_NULL_HANDLE);
    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;  // waits for the device
        resizeGeometryPass(device, geometryPass, target.extent);
        resizeLightingPass(device, lightingPass, target, geometryPass.gbuffer);
        recordLightingPass(device, lightingPass, target, lightingView);
        setProjection(geometryPass, common::projectionMatrix(scene.camera.fov, target.extent,
                                                             scene.camera.near, scene.camera.far));
        imageInFlight.assign(target.images.size(), VK_NULL_HANDLE);
        return true;
    };
    //< resize

    //> frame-loop
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V};
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(run, target, frame);
        uint32_t slot = frame % options.framesInFlight;
        Frame& inFlight = frames[slot];
        common::FrameSync& sync = inFlight.sync;

        if (target.window) {  // camera controls, and V cycles through the --view attachments
            double now = glfwGetTime();
            float speed = glm::length(gpuScene.boundsMax - gpuScene.boundsMin) * 0.15f;
            common::moveCamera(target.window, camera, cameraInput, float(now - lastTime), speed);
            lastTime = now;
            if (common::pressedOnce(target.window, viewKey)) {
                lightingView.view = (lightingView.view + 1) % int(kChapter.views.size());
                VK_CHECK(vkDeviceWaitIdle(device.handle));  // the lighting command buffers are re-recorded
                recordLightingPass(device, lightingPass, target, lightingView);
            }
        }

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::collectGpuTimes(run, device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        // The lighting command buffer of this image is reused as recorded: the frame that last
        // submitted it must be finished (it may have used the other frame-in-flight slot).
        if (imageInFlight[imageIndex] != VK_NULL_HANDLE && imageInFlight[imageIndex] != sync.inFlight)
            VK_CHECK(vkWaitForFences(device.handle, 1, &imageInFlight[imageIndex], VK_TRUE, UINT64_MAX));
        imageInFlight[imageIndex] = sync.inFlight;
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));

        // Geometry pass: recorded every frame (the camera moves), submitted on its own, and it
        // signals geometryComplete. It does not touch the target image, so it does not wait for it.
        setView(geometryPass, slot, common::viewMatrix(camera));
        VK_CHECK(vkResetCommandPool(device.handle, inFlight.geometryPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(inFlight.geometryCommands, &beginInfo));
        common::timeFrameStart(run, inFlight.geometryCommands, slot, frame);
        recordGeometryPass(inFlight.geometryCommands, geometryPass, gpuScene, slot);
        common::timePassEnd(run, inFlight.geometryCommands, slot, 0);
        VK_CHECK(vkEndCommandBuffer(inFlight.geometryCommands));
        VkSubmitInfo geometrySubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .commandBufferCount = 1,
            .pCommandBuffers = &inFlight.geometryCommands,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &inFlight.geometryComplete,
        };
        VK_CHECK(vkQueueSubmit(device.queue, 1, &geometrySubmit, VK_NULL_HANDLE));

        // Lighting pass: its pre-recorded command buffer for this image. It waits for the
        // G-buffer where it first reads it (the fragment shader) and for the image where it
        // first writes it (colour output); it signals the image's renderFinished and the
        // frame's fence, which therefore also covers the geometry submission before it.
        VkSemaphore waits[] = {inFlight.geometryComplete, sync.imageAvailable};
        VkPipelineStageFlags waitStages[] = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                                             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkCommandBuffer lighting[] = {lightingPass.commandBuffers[imageIndex], sync.commandBuffer};
        if (run.benchmark) {
            VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
            VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
            common::timePassEnd(run, sync.commandBuffer, slot, 1);
            VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
        }
        VkSubmitInfo lightingSubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .waitSemaphoreCount = 2,
            .pWaitSemaphores = waits,
            .pWaitDstStageMask = waitStages,
            .commandBufferCount = run.benchmark ? 2u : 1u,
            .pCommandBuffers = lighting,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &target.renderFinished[imageIndex],
        };
        VK_CHECK(vkQueueSubmit(device.queue, 1, &lightingSubmit, sync.inFlight));

        if (lastFrame) common::screenshotLastFrame(run, device, target, imageIndex);
        bool current = common::presentTargetImage(target, device, imageIndex);
        common::endFrame(run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget()) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    //< frame-loop
    common::reportRun(run, device, common::benchmarkInfo(kChapter, options, device, target));

    //> teardown
    common::destroyRunControl(device, run);
    common::savePipelineCache(device, pipelineCache);
    destroyLightingPass(device, lightingPass);
    destroyGeometryPass(device, geometryPass);
    common::destroyPipelineCache(device, pipelineCache);
    common::destroyGpuScene(device, gpuScene);
    destroyFrames(device, frames);
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
