// chapter-06: drawing a triangle -- the book's chapter 6 in C++.
//
// What is new here, in the book's order: buffers and the staging copy (loadMeshes), the vertex
// input description, SPIR-V shader modules, the pipeline cache and the graphics pipeline, and a
// frame loop that re-records its command buffer every frame. Instance, device, swapchain and
// command buffers come from earlier chapters of the book and live in common/.
#include <vulkan/vulkan.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

#include "common/benchmark.hpp"
#include "common/buffer.hpp"
#include "common/check.hpp"
#include "common/cli.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/files.hpp"
#include "common/instance.hpp"
#include "common/pipeline.hpp"
#include "common/screenshot.hpp"
#include "common/target.hpp"

namespace {

const common::ChapterInfo kChapter{"chapter-06", "drawing a triangle (the book's chapter 6)", {}};

//> mesh-data
// The book's MeshData: what the application knows about a mesh before the GPU has it.
struct MeshData {
    std::vector<float> positions;  // x, y, z per vertex
    std::vector<uint32_t> indices;
};

// The book's VulkanMesh: the same data in device-local buffers.
struct Mesh {
    common::Buffer vertices;
    common::Buffer indices;
    uint32_t indexCount = 0;
};
//< mesh-data

//> load-meshes
// Every mesh goes through a host-visible staging buffer into a device-local one. All copies are
// recorded into one command buffer, submitted once and waited for once (common::endStaging).
std::vector<Mesh> loadMeshes(const common::Device& device, const std::vector<MeshData>& meshData) {
    common::StagingBatch batch = common::beginStaging(device);
    std::vector<Mesh> meshes;
    for (const MeshData& data : meshData) {
        Mesh mesh;
        mesh.vertices =
            common::uploadStaged(device, batch, data.positions.data(), data.positions.size() * sizeof(float),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        mesh.indices =
            common::uploadStaged(device, batch, data.indices.data(), data.indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        mesh.indexCount = static_cast<uint32_t>(data.indices.size());
        meshes.push_back(mesh);
    }
    common::endStaging(device, batch);
    return meshes;
}
//< load-meshes

//> vertex-input
// The book's VertexBufferStructure: one binding of tightly packed vertices, one attribute
// (location 0, three 32-bit floats) for the position.
struct VertexInput {
    VkVertexInputBindingDescription binding;
    VkVertexInputAttributeDescription position;
    VkPipelineVertexInputStateCreateInfo state;
};

void describeVertexInput(VertexInput& input) {
    input.binding = {
        .binding = 0,
        .stride = 3 * sizeof(float),
        .inputRate = VK_VERTEX_INPUT_RATE_VERTEX,  // one element per vertex, not per instance
    };
    input.position = {
        .location = 0,
        .binding = 0,
        .format = VK_FORMAT_R32G32B32_SFLOAT,
        .offset = 0,
    };
    input.state = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = 1,
        .pVertexBindingDescriptions = &input.binding,
        .vertexAttributeDescriptionCount = 1,
        .pVertexAttributeDescriptions = &input.position,
    };
}
//< vertex-input

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

void destroyFramebuffers(const common::Device& device, std::vector<VkFramebuffer>& framebuffers) {
    for (VkFramebuffer framebuffer : framebuffers) vkDestroyFramebuffer(device.handle, framebuffer, nullptr);
    framebuffers.clear();
}
//< render-pass

//> pipeline
// The book's ShaderProgram and Pipeline: two SPIR-V modules compiled at build time, an empty
// pipeline layout (no descriptors or push constants yet) and the fixed-function state.
struct Pipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline handle = VK_NULL_HANDLE;
};

Pipeline createPipeline(const common::Device& device, VkPipelineCache cache, VkRenderPass renderPass,
                        const VertexInput& vertexInput) {
    VkShaderModule vertex = common::loadShaderModule(device, "chapter-06/triangle.vert");
    VkShaderModule fragment = common::loadShaderModule(device, "chapter-06/triangle.frag");

    Pipeline pipeline;
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pipeline.layout));

    common::GraphicsPipelineDesc desc{
        .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                   common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment)},
        .vertexInput = &vertexInput.state,
        .colorAttachmentCount = 1,
        .layout = pipeline.layout,
        .renderPass = renderPass,
    };
    pipeline.handle = common::createGraphicsPipeline(device, cache, desc);

    // The pipeline keeps what it needs; the modules can go.
    vkDestroyShaderModule(device.handle, fragment, nullptr);
    vkDestroyShaderModule(device.handle, vertex, nullptr);
    return pipeline;
}
//< pipeline

//> record
// Re-recorded every frame, as the book does from this chapter on.
void recordCommandBuffer(VkCommandBuffer cmd, VkRenderPass renderPass, VkFramebuffer framebuffer,
                         VkExtent2D extent, const Pipeline& pipeline, const std::vector<Mesh>& meshes,
                         common::GpuTimer* timer, uint32_t slot, uint32_t frame) {
    VkCommandBufferBeginInfo beginInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
    if (timer) common::beginGpuTimer(*timer, cmd, slot, frame);  // --benchmark only

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
    if (timer) common::markGpuPass(*timer, cmd, slot, 0);
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
    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-06");
    Pipeline pipeline = createPipeline(device, pipelineCache.handle, renderPass, vertexInput);

    // --benchmark: a timestamp before and after the one pass, and the frame statistics.
    common::GpuTimer gpuTimer = common::createGpuTimer(device, options.framesInFlight, {"triangle"});
    common::FrameStats stats = common::createFrameStats(options, gpuTimer.passes);
    //< setup

    //> frame-loop
    // After a resize only the images change size; the render pass and the pipeline (viewport and
    // scissor are dynamic) stay, the framebuffers that point at the images are rebuilt.
    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;
        destroyFramebuffers(device, framebuffers);
        framebuffers = createFramebuffers(device, renderPass, target);
        return true;
    };

    for (uint32_t frame = 0;;) {
        auto frameStart = std::chrono::steady_clock::now();
        bool lastFrame = common::pollTarget(target, frame);
        common::FrameSync& sync = frames[frame % options.framesInFlight];

        // Wait until the GPU is done with this slot's command buffer, used options.framesInFlight frames ago.
        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        if (options.benchmark) common::readGpuTimer(device, gpuTimer, frame % options.framesInFlight, stats);

        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget()) break;
            continue;
        }
        VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));

        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        recordCommandBuffer(sync.commandBuffer, renderPass, framebuffers[imageIndex], target.extent, pipeline,
                            meshes, options.benchmark ? &gpuTimer : nullptr, frame % options.framesInFlight,
                            frame);

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
    vkDestroyPipeline(device.handle, pipeline.handle, nullptr);
    vkDestroyPipelineLayout(device.handle, pipeline.layout, nullptr);
    common::destroyPipelineCache(device, pipelineCache);
    destroyFramebuffers(device, framebuffers);
    vkDestroyRenderPass(device.handle, renderPass, nullptr);
    for (Mesh& mesh : meshes) {
        common::destroyBuffer(device, mesh.indices);
        common::destroyBuffer(device, mesh.vertices);
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
