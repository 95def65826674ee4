// The GUI pass for chapter-15: Dear ImGui's draw data drawn by our own pipeline onto the presented
// image, after the post pass. chapter-14/gui_pass.cpp writes it out for the reader, as the chapter
// that introduces it; this is the same code, shared from here as common wraps every Vulkan call
// for the chapters after the one that introduces it.
#pragma once

#include <imgui.h>
#include <vulkan/vulkan.h>

#include <vector>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/image.hpp"
#include "common/target.hpp"

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
    std::vector<GuiFrame> frames;
    uint32_t growths = 0;                            // how often a frame's buffers grew (reported at the end)
    size_t largestVertices = 0, largestIndices = 0;  // the most one frame drew
};

// After ImGui's context exists (its font atlas is uploaded here). `format`: the presented image's.
GuiPass createGuiPass(const common::Device& device, VkPipelineCache cache, VkFormat format,
                      uint32_t framesInFlight);
// Copies this frame's draw data (nullptr: none) into its buffers, growing them if needed. After
// the frame's fence.
void updateGuiBuffers(const common::Device& device, GuiPass& pass, uint32_t frame, const ImDrawData* draw);
// Draws `draw` (nullptr: nothing) over presented image `imageIndex`, which the post pass left in
// ATTACHMENT_OPTIMAL, and moves the image to its present layout.
void recordGuiPass(VkCommandBuffer cmd, const GuiPass& pass, uint32_t frame, const common::Target& target,
                   uint32_t imageIndex, const ImDrawData* draw);
void destroyGuiPass(const common::Device& device, GuiPass& pass);

}  // namespace common
