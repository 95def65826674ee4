// chapter-10: deferred shading with render passes -- the book's chapter 10 in C++.
//
// The frame is split in two passes, each with its own VkRenderPass and framebuffer, recorded
// into their own command buffers and submitted separately, joined by a semaphore:
//   geometry pass (geometry_pass.cpp): the scene into a G-buffer of albedo + depth;
//   lighting pass (lighting_pass.cpp): a full-screen triangle into the target image, reading the
//   G-buffer. There is no lighting yet -- it copies albedo, as the book does -- until chapter-15.
// Models, textures, the scene file and the camera (the book's chapters 7-9) come from common/.
#include <vulkan/vulkan.h>

#include <chrono>
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
#include "common/scene.hpp"
#include "common/screenshot.hpp"
#include "common/target.hpp"
#include "geometry_pass.hpp"
#include "lighting_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-10",
    "deferred shading with render passes (the book's chapter 10)",
    {"final", "albedo", "depth"},  // --view names; their order is the lighting shader's `view`
};

// Per frame in flight, on top of common::FrameSync: the geometry pass's own command buffer and
// the semaphore that tells the lighting submission the G-buffer is written.
struct GeometrySync {
    VkCommandPool commandPool;
    VkCommandBuffer commandBuffer;
    VkSemaphore geometryComplete;
};

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
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);
    std::vector<GeometrySync> geometrySync(options.framesInFlight);
    for (GeometrySync& sync : geometrySync) {
        VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                         .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                         .queueFamilyIndex = device.queueFamily};
        VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &sync.commandPool));
        VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = sync.commandPool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &sync.commandBuffer));
        sync.geometryComplete = common::createSemaphore(device);
    }

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
    common::GpuTimer gpuTimer =
        common::createGpuTimer(device, options.framesInFlight, {"geometry", "lighting"});
    common::FrameStats stats = common::createFrameStats(options, gpuTimer.passes);
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
    bool viewKeyDown = false;
    for (uint32_t frame = 0;;) {
        auto frameStart = std::chrono::steady_clock::now();
        bool lastFrame = common::pollTarget(target, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];
        GeometrySync& geometry = geometrySync[slot];

        if (target.window) {  // camera controls, and V cycles through the --view attachments
            double now = glfwGetTime();
            float speed = glm::length(gpuScene.boundsMax - gpuScene.boundsMin) * 0.15f;
            common::moveCamera(target.window, camera, cameraInput, float(now - lastTime), speed);
            lastTime = now;
            bool viewKey = glfwGetKey(target.window, GLFW_KEY_V) == GLFW_PRESS;
            if (viewKey && !viewKeyDown) {
                lightingView.view = (lightingView.view + 1) % int(kChapter.views.size());
                VK_CHECK(vkDeviceWaitIdle(device.handle));  // the lighting command buffers are re-recorded
                recordLightingPass(device, lightingPass, target, lightingView);
            }
            viewKeyDown = viewKey;
        }

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        if (options.benchmark) common::readGpuTimer(device, gpuTimer, slot, stats);
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
        VK_CHECK(vkResetCommandPool(device.handle, geometry.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(geometry.commandBuffer, &beginInfo));
        if (options.benchmark) common::beginGpuTimer(gpuTimer, geometry.commandBuffer, slot, frame);
        recordGeometryPass(geometry.commandBuffer, geometryPass, gpuScene, slot);
        if (options.benchmark) common::markGpuPass(gpuTimer, geometry.commandBuffer, slot, 0);
        VK_CHECK(vkEndCommandBuffer(geometry.commandBuffer));
        VkSubmitInfo geometrySubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .commandBufferCount = 1,
            .pCommandBuffers = &geometry.commandBuffer,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &geometry.geometryComplete,
        };
        VK_CHECK(vkQueueSubmit(device.queue, 1, &geometrySubmit, VK_NULL_HANDLE));

        // Lighting pass: its pre-recorded command buffer for this image. It waits for the
        // G-buffer where it first reads it (the fragment shader) and for the image where it
        // first writes it (colour output); it signals the image's renderFinished and the
        // frame's fence, which therefore also covers the geometry submission before it.
        VkSemaphore waits[] = {geometry.geometryComplete, sync.imageAvailable};
        VkPipelineStageFlags waitStages[] = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                                             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkCommandBuffer lighting[] = {lightingPass.commandBuffers[imageIndex], sync.commandBuffer};
        if (options.benchmark) {
            VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
            VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
            common::markGpuPass(gpuTimer, sync.commandBuffer, slot, 1);
            VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
        }
        VkSubmitInfo lightingSubmit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .waitSemaphoreCount = 2,
            .pWaitSemaphores = waits,
            .pWaitDstStageMask = waitStages,
            .commandBufferCount = options.benchmark ? 2u : 1u,
            .pCommandBuffers = lighting,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &target.renderFinished[imageIndex],
        };
        VK_CHECK(vkQueueSubmit(device.queue, 1, &lightingSubmit, sync.inFlight));

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
        common::reportBenchmark(stats, common::benchmarkInfo(kChapter, options, device, target));
    }

    //> teardown
    common::destroyGpuTimer(device, gpuTimer);
    common::savePipelineCache(device, pipelineCache);
    destroyLightingPass(device, lightingPass);
    destroyGeometryPass(device, geometryPass);
    common::destroyPipelineCache(device, pipelineCache);
    common::destroyGpuScene(device, gpuScene);
    for (GeometrySync& sync : geometrySync) {
        vkDestroySemaphore(device.handle, sync.geometryComplete, nullptr);
        vkDestroyCommandPool(device.handle, sync.commandPool, nullptr);
    }
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
