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
#include "common/check.hpp"
#include "common/cli.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/instance.hpp"
#include "common/pipeline.hpp"
#include "common/run_control.hpp"
#include "common/target.hpp"
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
                         VkExtent2D extent, const Pipeline& pipeline, const std::vector<Mesh>& meshes,
                         common::RunControl& run, uint32_t slot, uint32_t frame) {
    VkCommandBufferBeginInfo beginInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
    common::timeFrameStart(run, cmd, slot, frame);  // --benchmark only

    VkClearValue clear{.color = {{0.5f, 0.7f, 0.9f, 1.0f}}};
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
    common::timePassEnd(run, cmd, slot, 0);
    VK_CHECK(vkEndCommandBuffer(cmd));
}
//< record

void run(const common::Options& options) {
    //> setup
    common::Target target = common::openTarget(options, "chapter-06: drawing a triangle");
    common::Instance instance =
        common::createInstance("chapter-06", options.validation, common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    common::Device device = common::createDevice(instance, target.surface, options.device);
    common::createTargetImages(target, device);
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);

    // The book's order: the data to the GPU, its description, then the pipeline that draws it.
    std::vector<Mesh> meshes = loadMeshes(device, {MeshData{
                                                      .positions = {-0.5f, -0.5f, 0.0f,  //
                                                                    0.0f, 0.5f, 0.0f,    //
                                                                    0.5f, -0.5f, 0.0f},
                                                      .indices = {0, 1, 2},
                                                  }});
    VertexInput vertexInput;
    describeVertexInput(vertexInput);
    VkRenderPass renderPass = createRenderPass(device, target.format, target.presentLayout);
    std::vector<VkFramebuffer> framebuffers = createFramebuffers(device, renderPass, target);
    common::PipelineCache pipelineCache = createPipelineCache(device);
    Pipeline pipeline = createPipeline(device, pipelineCache.handle, renderPass, vertexInput);

    // --frames, --resize, --benchmark (one timed pass), --screenshot.
    common::RunControl run = common::createRunControl(options, device, {"triangle"});
    //< setup

    //> frame-loop
    // After a resize only the images change size; the render pass and the pipeline (viewport and
    // scissor are dynamic) stay, the framebuffers that point at the images are rebuilt.
    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;
        destroyFramebuffers(device.handle, framebuffers);
        framebuffers = createFramebuffers(device, renderPass, target);
        return true;
    };

    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(run, target, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];

        // Wait until the GPU is done with this slot's command buffer, used options.framesInFlight frames ago.
        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::collectGpuTimes(run, device, slot);

        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));

        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        recordCommandBuffer(sync.commandBuffer, renderPass, framebuffers[imageIndex], target.extent, pipeline,
                            meshes, run, slot, frame);

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
            .pSignalSemaphores = &target.renderFinished[imageIndex],
        };
        VK_CHECK(vkQueueSubmit(device.queue, 1, &submit, sync.inFlight));

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
    destroyPipeline(device, pipeline);
    common::destroyPipelineCache(device, pipelineCache);
    destroyFramebuffers(device.handle, framebuffers);
    vkDestroyRenderPass(device.handle, renderPass, nullptr);
    destroyMeshes(device, meshes);
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
