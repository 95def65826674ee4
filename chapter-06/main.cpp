// chapter-06: drawing a triangle -- the book's chapter 6 in C++.
//
// What is new here, in the book's order: buffers (buffer.cpp), the vertex input description and
// the staging copy of the meshes (mesh.cpp), SPIR-V shader modules, the pipeline cache and the
// graphics pipeline (pipeline.cpp), and a frame loop that records its command buffer every frame
// (below). Instance, device, swapchain, render pass basics and command buffers come from earlier
// chapters of the book; this first chapter of ours still writes out its render pass and
// framebuffers (later chapters take the target's from common/).
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "buffer.hpp"
#include "common/app/cli.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/device.hpp"
#include "common/vk/formats.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"
#include "mesh.hpp"
#include "pipeline.hpp"

namespace {

const common::ChapterInfo kChapter{"chapter-06", "drawing a triangle (the book's chapter 6)", {}};

//> render-pass
// One colour attachment, the target image: cleared on load, stored, and left in the layout the
// target presents from. The dependency makes the clear wait for the image to be acquired:
// acquireTargetImage's semaphore is waited at COLOR_ATTACHMENT_OUTPUT, so the layout
// transition and the writes of this pass must not start before that stage.
VkRenderPass createRenderPass(const common::Device& device, VkFormat format, VkImageLayout presentLayout) {
    VkAttachmentDescription color{
        .format = format,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
        .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,  // the old content is cleared anyway
        .finalLayout = presentLayout,
    };
    VkAttachmentReference colorRef{.attachment = 0, .layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{
        .pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
        .colorAttachmentCount = 1,
        .pColorAttachments = &colorRef,
    };
    VkSubpassDependency acquire{
        .srcSubpass = VK_SUBPASS_EXTERNAL,
        .dstSubpass = 0,
        .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        .srcAccessMask = 0,
        .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
    };
    VkRenderPassCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
        .attachmentCount = 1,
        .pAttachments = &color,
        .subpassCount = 1,
        .pSubpasses = &subpass,
        .dependencyCount = 1,
        .pDependencies = &acquire,
    };
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(device.handle, &info, nullptr, &renderPass));
    common::nameObject(device.handle, renderPass, "triangle");
    return renderPass;
}

// One framebuffer per target image: which image the render pass's attachment 0 is. (Deliberate
// repetition: common::createTargetFramebuffers is the same, for the later chapters.)
std::vector<VkFramebuffer> createFramebuffers(const common::Device& device, VkRenderPass renderPass,
                                              const common::Target& target) {
    std::vector<VkFramebuffer> framebuffers(target.views.size());
    for (size_t i = 0; i < target.views.size(); ++i) {
        VkFramebufferCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
            .renderPass = renderPass,
            .attachmentCount = 1,
            .pAttachments = &target.views[i],
            .width = target.extent.width,
            .height = target.extent.height,
            .layers = 1,
        };
        VK_CHECK(vkCreateFramebuffer(device.handle, &info, nullptr, &framebuffers[i]));
        common::nameObject(device.handle, framebuffers[i],
                           std::string("target image ").append(std::to_string(i)));
    }
    return framebuffers;
}

void destroyFramebuffers(VkDevice device, std::vector<VkFramebuffer>& framebuffers) {
    for (VkFramebuffer framebuffer : framebuffers) vkDestroyFramebuffer(device, framebuffer, nullptr);
    framebuffers.clear();
}
//< render-pass

//> record
// Re-recorded every frame, as the book does from this chapter on.
void recordCommandBuffer(VkCommandBuffer cmd, VkRenderPass renderPass, VkFramebuffer framebuffer,
                         VkExtent2D extent, VkFormat format, const Pipeline& pipeline,
                         const std::vector<Mesh>& meshes, common::RunControl& run, uint32_t slot,
                         uint32_t frame) {
    VkCommandBufferBeginInfo beginInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
    common::timeFrameStart(run, cmd, slot, frame);  // --benchmark only
    common::beginPass(run, cmd, 0);                 // a debugger's label: "triangle"

    // A linear colour, as the shader's; encoded here where the target's format does not.
    VkClearValue clear{.color = {{0.5f, 0.7f, 0.9f, 1.0f}}};
    if (!common::encodesSrgb(format))
        for (int c = 0; c < 3; ++c) clear.color.float32[c] = common::encodeSrgb(clear.color.float32[c]);
    VkRenderPassBeginInfo passInfo{
        .sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
        .renderPass = renderPass,
        .framebuffer = framebuffer,
        .renderArea = {{0, 0}, extent},
        .clearValueCount = 1,
        .pClearValues = &clear,
    };
    vkCmdBeginRenderPass(cmd, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle);

    // Flipped viewport: y starts at the bottom and the height is negative, so +y points up as in
    // OpenGL and the book's models (a core feature since Vulkan 1.1).
    VkViewport viewport{
        .x = 0.0f,
        .y = static_cast<float>(extent.height),
        .width = static_cast<float>(extent.width),
        .height = -static_cast<float>(extent.height),
        .minDepth = 0.0f,
        .maxDepth = 1.0f,
    };
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetScissor(cmd, 0, 1, &scissor);

    for (const Mesh& mesh : meshes) {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &mesh.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, 0, 0, 0);
    }

    vkCmdEndRenderPass(cmd);
    common::endPass(run, cmd, slot, 0);
    VK_CHECK(vkEndCommandBuffer(cmd));
}
//< record

//> chapter-state
// Everything the chapter makes, in the order setUp() makes it; tearDown() destroys it in reverse.
// Made in place, never moved: the pipeline's vertex input description points into itself
// (VertexInput, mesh.hpp).
struct Chapter {
    common::Target target;
    common::Instance instance;
    common::Device device;
    std::vector<common::FrameSync> frames;
    std::vector<Mesh> meshes;
    VertexInput vertexInput{};
    VkRenderPass renderPass = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers;
    common::PipelineCache pipelineCache;
    Pipeline pipeline;
    common::RunControl run;  // --frames, --resize, --benchmark (one timed pass), --screenshot
};
//< chapter-state

//> setup
void setUp(Chapter& c, const common::Options& options) {
    c.target = common::openTarget(options, "chapter-06: drawing a triangle");
    c.instance =
        common::createInstance("chapter-06", options.validation, common::targetInstanceExtensions(c.target));
    common::createTargetSurface(c.target, c.instance);
    c.device = common::createDevice(c.instance, c.target.surface, options.device);
    common::createTargetImages(c.target, c.device);
    c.frames = common::createFrameSync(c.device, options.framesInFlight);

    // The book's order: the data to the GPU, its description, then the pipeline that draws it.
    c.meshes = loadMeshes(c.device, {MeshData{
                                        .positions = {-0.5f, -0.5f, 0.0f,  //
                                                      0.0f, 0.5f, 0.0f,    //
                                                      0.5f, -0.5f, 0.0f},
                                        .indices = {0, 1, 2},
                                    }});
    describeVertexInput(c.vertexInput);
    c.renderPass = createRenderPass(c.device, c.target.format, c.target.presentLayout);
    c.framebuffers = createFramebuffers(c.device, c.renderPass, c.target);
    c.pipelineCache = createPipelineCache(c.device);
    c.pipeline =
        createPipeline(c.device, c.pipelineCache.handle, c.renderPass, c.vertexInput, c.target.format);
    c.run = common::createRunControl(options, c.device, {"triangle"});
}
//< setup

//> resize
// After a resize only the images change size; the render pass and the pipeline (viewport and
// scissor are dynamic) stay, the framebuffers that point at the images are rebuilt. Unless the
// images' format changed too (the window moved to a screen with other formats): the render pass
// describes the format, and the pipeline is made for the render pass and encodes for the format.
bool recreateTarget(Chapter& c) {
    VkFormat format = c.target.format;
    if (!common::recreateTargetImages(c.target, c.device)) return false;
    if (c.target.format != format) {
        destroyPipeline(c.device, c.pipeline);
        vkDestroyRenderPass(c.device.handle, c.renderPass, nullptr);
        c.renderPass = VK_NULL_HANDLE;
        c.renderPass = createRenderPass(c.device, c.target.format, c.target.presentLayout);
        c.pipeline =
            createPipeline(c.device, c.pipelineCache.handle, c.renderPass, c.vertexInput, c.target.format);
    }
    destroyFramebuffers(c.device.handle, c.framebuffers);
    c.framebuffers = createFramebuffers(c.device, c.renderPass, c.target);
    return true;
}
//< resize

//> reload
// Live reload: an edited shader compiled and checked (common/shaders/shader_watch.hpp). The new pipeline
// is made from that code while the frames in flight still draw with the old one; once the GPU is
// done with them, it takes the old one's place. If it cannot be made, the old one keeps drawing
// and the error is shown.
void reloadShaders(Chapter& c) {
    Pipeline pipeline;
    try {
        pipeline =
            createPipeline(c.device, c.pipelineCache.handle, c.renderPass, c.vertexInput, c.target.format);
    } catch (const std::exception& e) {
        common::finishShaderReload(e.what());
        return;
    }
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
    destroyPipeline(c.device, c.pipeline);
    c.pipeline = pipeline;
    common::finishShaderReload();
}
//< reload

//> frame-loop
void frameLoop(Chapter& c, const common::Options& options) {
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(c.run, c.target, frame);
        if (common::pollShaderSources()) reloadShaders(c);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = c.frames[slot];

        // Wait until the GPU is done with this slot's command buffer, used options.framesInFlight frames ago.
        VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::collectGpuTimes(c.run, c.device, slot);

        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget(c)) break;
            continue;
        }
        VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));

        VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
        recordCommandBuffer(sync.commandBuffer, c.renderPass, c.framebuffers[imageIndex], c.target.extent,
                            c.target.format, c.pipeline, c.meshes, c.run, slot, frame);

        // Colour output waits for the image; the target's semaphore for this image says when the
        // drawing is done; the fence says when this frame's command buffer is free again.
        VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        VkSubmitInfo submit{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
            .waitSemaphoreCount = 1,
            .pWaitSemaphores = &sync.imageAvailable,
            .pWaitDstStageMask = &waitStage,
            .commandBufferCount = 1,
            .pCommandBuffers = &sync.commandBuffer,
            .signalSemaphoreCount = 1,
            .pSignalSemaphores = &c.target.renderFinished[imageIndex],
        };
        VK_CHECK(vkQueueSubmit(c.device.queue, 1, &submit, sync.inFlight));

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
    destroyPipeline(c.device, c.pipeline);
    common::destroyPipelineCache(c.device, c.pipelineCache);
    destroyFramebuffers(c.device.handle, c.framebuffers);
    vkDestroyRenderPass(c.device.handle, c.renderPass, nullptr);
    destroyMeshes(c.device, c.meshes);
    common::destroyFrameSync(c.device, c.frames);
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
    common::reportRun(chapter.run, chapter.device,
                      common::benchmarkInfo(kChapter, options, chapter.device, chapter.target));
    tearDown(chapter);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
