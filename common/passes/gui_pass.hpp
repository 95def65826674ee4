// The GUI pass of chapters 14 and 15 (--gui): Dear ImGui's draw data drawn by our own pipeline
// onto the presented image, after the post pass, as the book's GuiRender does. The widgets and
// input are common/app/gui.cpp. The book teaches its GUI in its chapter 12, which we do not carry: the
// pass lives here once, and chapter-14's page walks through it.
#pragma once

#include <imgui.h>
#include <vulkan/vulkan.h>

#include <vector>

#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"

namespace common {

// Per frame in flight: the vertices and indices of its draw data, in host-visible buffers that
// grow when the draw data outgrows them (the frame's fence has been waited for, so the old ones
// are free).
struct GuiFrame {
    common::Buffer vertices;  // ImDrawVert[vertexCapacity]
    common::Buffer indices;   // ImDrawIdx[indexCapacity]
    size_t vertexCapacity = 0, indexCapacity = 0;
};

struct GuiPass {
    common::Image fontAtlas;  // uploaded once
    VkSampler sampler = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet fontSet = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;  // of the view it draws through
    std::vector<GuiFrame> frames;
    uint32_t growths = 0;                            // how often a frame's buffers grew (reported at the end)
    size_t largestVertices = 0, largestIndices = 0;  // the most one frame drew
};

// After ImGui's context exists (its font atlas is uploaded here). `format`: that of the view the
// pass draws through, Target::encodedFormat (the _UNORM twin of an _SRGB image where the image can
// be viewed so, else the image's own).
GuiPass createGuiPass(const common::Device& device, VkPipelineCache cache, VkFormat format,
                      uint32_t framesInFlight);
// Live reload: a new pipeline into `swap` when the reload changed gui.vert or gui.frag.
void remakeGuiPipeline(const common::Device& device, VkPipelineCache cache, GuiPass& pass, VkFormat format,
                       const common::ShaderReload& reload, common::PipelineSwap& swap);
// After the target was made again: when the format of the view it draws through changed (the
// window moved to a screen with other formats), a pipeline for the new one. The device must be idle.
void retargetGuiPass(const common::Device& device, VkPipelineCache cache, GuiPass& pass, VkFormat format);
// Copies this frame's draw data (nullptr: none) into its buffers, growing them if needed. After
// the frame's fence.
void updateGuiBuffers(const common::Device& device, GuiPass& pass, uint32_t frame, const ImDrawData* draw);
// Draws `draw` (nullptr: nothing) over presented image `imageIndex`, which the post pass left in
// ATTACHMENT_OPTIMAL, and moves the image to its present layout.
void recordGuiPass(VkCommandBuffer cmd, const GuiPass& pass, uint32_t frame, const common::Target& target,
                   uint32_t imageIndex, const ImDrawData* draw);
void destroyGuiPass(const common::Device& device, GuiPass& pass);

}  // namespace common
