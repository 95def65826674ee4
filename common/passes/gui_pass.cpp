// The GUI pass of chapters 14 and 15: Dear ImGui's draw data drawn by our own pipeline onto the
// presented image, after the post pass, as the book's GuiRender does. The book teaches its GUI in
// its chapter 12, which we do not carry, so the pass lives here once and chapter-14's page walks
// through it (docs/chapter-14.md, "The GUI pass").
#include "common/passes/gui_pass.hpp"

#include <algorithm>
#include <cstring>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/formats.hpp"
#include "common/vk/pipeline.hpp"
#include "common/vk/texture.hpp"

namespace common {
namespace {

// The push constants of gui.vert: window points to clip space.
struct GuiTransform {
    float scale[2];
    float translate[2];
};

//> gui-pipeline
// Dear ImGui's vertex (ImDrawVert): position and font-atlas coordinate as two floats each, the
// colour as four bytes.
VkPipeline createGuiPipeline(const common::Device& device, VkPipelineCache cache, VkPipelineLayout layout,
                             VkFormat format) {
    // ImGui's colours are sRGB values, blended as they are. We draw through a _UNORM view of the
    // presented image (Target::encodedViews), so they are; only where the image has no such view
    // does the hardware encode, and the vertex shader decodes them first (constant_id 0), which
    // blends them in linear light instead.
    VkBool32 decodeSrgb = common::encodesSrgb(format) ? VK_TRUE : VK_FALSE;
    VkSpecializationMapEntry decodeEntry{0, 0, sizeof(VkBool32)};
    VkSpecializationInfo vertexConstants{1, &decodeEntry, sizeof(decodeSrgb), &decodeSrgb};
    common::ShaderModule vertex(device, "common/gui.vert");
    common::ShaderModule fragment(device, "common/gui.frag");
    VkVertexInputBindingDescription binding{0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, pos)},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, uv)},
        {2, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(ImDrawVert, col)},
    };
    VkPipelineVertexInputStateCreateInfo vertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = 1,
        .pVertexBindingDescriptions = &binding,
        .vertexAttributeDescriptionCount = 3,
        .pVertexAttributeDescriptions = attributes};
    // Dynamic rendering: the presented image's format, no depth.
    VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                            .colorAttachmentCount = 1,
                                            .pColorAttachmentFormats = &format};
    // ImGui's triangles face either way: no culling. Blending on: the overlay goes over the image
    // by its alpha. Viewport and scissor are dynamic (the scissor changes with every command).
    VkPipeline pipeline = common::createGraphicsPipeline(
        device, cache,
        {.name = "gui",
         .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex, &vertexConstants),
                    common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment)},
         .vertexInput = &vertexInput,
         .cullMode = VK_CULL_MODE_NONE,
         .alphaBlend = true,
         .layout = layout,
         .pNext = &rendering});
    return pipeline;
}
//< gui-pipeline

// Makes room in a frame's buffers for `draw`: a growing buffer doubles, so a window that opens
// with much text costs one or two growths, not one per frame.
void reserve(const common::Device& device, GuiPass& pass, GuiFrame& frame, const ImDrawData& draw) {
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    size_t vertices = size_t(std::max(draw.TotalVtxCount, 1)),
           indices = size_t(std::max(draw.TotalIdxCount, 1));
    pass.largestVertices = std::max(pass.largestVertices, vertices);
    pass.largestIndices = std::max(pass.largestIndices, indices);
    if (vertices > frame.vertexCapacity) {
        common::destroyBuffer(device, frame.vertices);
        frame.vertexCapacity = std::max(vertices, frame.vertexCapacity * 2);
        frame.vertices = common::createBuffer(device, frame.vertexCapacity * sizeof(ImDrawVert),
                                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, hostVisible, "gui vertices");
        ++pass.growths;
    }
    if (indices > frame.indexCapacity) {
        common::destroyBuffer(device, frame.indices);
        frame.indexCapacity = std::max(indices, frame.indexCapacity * 2);
        frame.indices = common::createBuffer(device, frame.indexCapacity * sizeof(ImDrawIdx),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT, hostVisible, "gui indices");
        ++pass.growths;
    }
}

}  // namespace

void remakeGuiPipeline(const common::Device& device, VkPipelineCache cache, GuiPass& pass, VkFormat format,
                       const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (!reload.changed({"common/gui.vert", "common/gui.frag"})) return;
    common::replacePipeline(swap, pass.pipeline,
                            [&] { return createGuiPipeline(device, cache, pass.pipelineLayout, format); });
}

void retargetGuiPass(const common::Device& device, VkPipelineCache cache, GuiPass& pass, VkFormat format) {
    if (pass.pipeline == VK_NULL_HANDLE || format == pass.format) return;
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    pass.pipeline = VK_NULL_HANDLE;
    pass.pipeline = createGuiPipeline(device, cache, pass.pipelineLayout, format);
    pass.format = format;
}

GuiPass createGuiPass(const common::Device& device, VkPipelineCache cache, VkFormat format,
                      uint32_t framesInFlight) {
    GuiPass pass;
    //> gui-font
    // The font atlas: ImGui rasterises its font into RGBA pixels once; they become a sampled image.
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    common::Pixels atlas{uint32_t(width), uint32_t(height),
                         std::vector<uint8_t>(pixels, pixels + size_t(width) * size_t(height) * 4)};
    common::StagingBatch batch = common::beginStaging(device);
    pass.fontAtlas = common::uploadTexture(device, batch, atlas, VK_FORMAT_R8G8B8A8_UNORM, "gui font");
    common::endStaging(device, batch);
    pass.sampler =
        common::createSampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f);
    //< gui-font
    pass.setLayout = common::createDescriptorSetLayout(
        device, {common::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)},
        "gui font");
    pass.descriptorPool =
        common::createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}}, "gui");
    pass.fontSet = common::allocateDescriptorSet(device, pass.descriptorPool, pass.setLayout, "gui font");
    common::writeImageDescriptor(device, pass.fontSet, 0, pass.sampler, pass.fontAtlas.view,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(GuiTransform)};
    pass.pipelineLayout = createPipelineLayout(device, {&pass.setLayout, 1}, {&push, 1}, "gui");
    pass.pipeline = createGuiPipeline(device, cache, pass.pipelineLayout, format);
    pass.format = format;
    pass.frames.resize(framesInFlight);
    return pass;
}

//> update-gui
void updateGuiBuffers(const common::Device& device, GuiPass& pass, uint32_t frame, const ImDrawData* draw) {
    if (!draw || draw->TotalIdxCount == 0) return;
    GuiFrame& buffers = pass.frames[frame];
    reserve(device, pass, buffers, *draw);
    // This frame's vertices and indices, every draw list's one after another.
    auto* vertices = static_cast<ImDrawVert*>(buffers.vertices.mapped);
    auto* indices = static_cast<ImDrawIdx*>(buffers.indices.mapped);
    for (int n = 0; n < draw->CmdListsCount; ++n) {
        const ImDrawList* list = draw->CmdLists[n];
        vertices = std::copy_n(list->VtxBuffer.Data, list->VtxBuffer.Size, vertices);
        indices = std::copy_n(list->IdxBuffer.Data, list->IdxBuffer.Size, indices);
    }
}
//< update-gui

//> record-gui
void recordGuiPass(VkCommandBuffer cmd, const GuiPass& pass, uint32_t frame, const common::Target& target,
                   uint32_t imageIndex, const ImDrawData* draw) {
    bool drawing = draw && draw->TotalIdxCount > 0;
    const GuiFrame& buffers = pass.frames[frame];

    // Over what the post pass wrote: after its writes (two renderings are not ordered by
    // themselves), load it, draw, store.
    VkImageMemoryBarrier2 after = common::imageBarrier(
        target.images[imageIndex], VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    common::pipelineBarrier(cmd, &after, 1);
    VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = target.encodedViews[imageIndex],
                                    .imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                                    .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, target.extent},
                              .layerCount = 1,
                              .colorAttachmentCount = 1,
                              .pColorAttachments = &color};
    vk13.CmdBeginRendering(cmd, &rendering);
    if (drawing) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipelineLayout, 0, 1,
                                &pass.fontSet, 0, nullptr);
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &buffers.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, buffers.indices.handle, 0,
                             sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
        // ImGui's coordinates are window points, y down: Vulkan's own viewport orientation (not
        // flipped). The transform maps the display's points to clip space and the viewport
        // covers the image's pixels, so on a HiDPI display (FramebufferScale 2: two pixels a
        // point) the overlay covers the same part of the window at twice the detail.
        VkViewport viewport{0.0f, 0.0f, float(target.extent.width), float(target.extent.height), 0.0f, 1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        ImVec2 scale = draw->FramebufferScale;
        GuiTransform transform{{2.0f / draw->DisplaySize.x, 2.0f / draw->DisplaySize.y},
                               {-1.0f - draw->DisplayPos.x * 2.0f / draw->DisplaySize.x,
                                -1.0f - draw->DisplayPos.y * 2.0f / draw->DisplaySize.y}};
        vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(transform),
                           &transform);
        // One draw per command, clipped by its scissor rectangle (points to pixels, inside the image).
        uint32_t firstVertex = 0, firstIndex = 0;
        for (int n = 0; n < draw->CmdListsCount; ++n) {
            const ImDrawList* list = draw->CmdLists[n];
            for (const ImDrawCmd& command : list->CmdBuffer) {
                float x0 = std::max((command.ClipRect.x - draw->DisplayPos.x) * scale.x, 0.0f);
                float y0 = std::max((command.ClipRect.y - draw->DisplayPos.y) * scale.y, 0.0f);
                float x1 =
                    std::min((command.ClipRect.z - draw->DisplayPos.x) * scale.x, float(target.extent.width));
                float y1 = std::min((command.ClipRect.w - draw->DisplayPos.y) * scale.y,
                                    float(target.extent.height));
                if (x1 <= x0 || y1 <= y0) continue;
                VkRect2D scissor{{int32_t(x0), int32_t(y0)}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
                vkCmdSetScissor(cmd, 0, 1, &scissor);
                vkCmdDrawIndexed(cmd, command.ElemCount, 1, firstIndex + command.IdxOffset,
                                 int32_t(firstVertex + command.VtxOffset), 0);
            }
            firstVertex += uint32_t(list->VtxBuffer.Size);
            firstIndex += uint32_t(list->IdxBuffer.Size);
        }
    }
    vk13.CmdEndRendering(cmd);

    // renderFinish: to the layout the target presents from.
    VkImageMemoryBarrier2 finish = common::imageBarrier(
        target.images[imageIndex], VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
        target.presentLayout, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    common::pipelineBarrier(cmd, &finish, 1);
}
//< record-gui

void destroyGuiPass(const common::Device& device, GuiPass& pass) {
    for (GuiFrame& frame : pass.frames) {
        common::destroyBuffer(device, frame.indices);
        common::destroyBuffer(device, frame.vertices);
    }
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.setLayout, nullptr);
    vkDestroySampler(device.handle, pass.sampler, nullptr);
    common::destroyImage(device, pass.fontAtlas);
    pass = {};
}

}  // namespace common
