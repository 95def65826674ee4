// chapter-06: shaders and the graphics pipeline -- the book's ShaderProgram (SPIR-V modules),
// PipelineCache and Pipeline (every fixed-function state struct, then vkCreateGraphicsPipelines).
//
// Deliberate repetition: common/shaders/shader_compiler.cpp (loadShaderModule) and common/vk/pipeline.cpp
// (loadPipelineCache, createGraphicsPipeline) hold the same calls for the later chapters, which
// use them without spelling them out again. This chapter introduces them, so here they are.
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"
#include "mesh.hpp"

VkShaderModule createShaderModule(const common::Device& device, std::string_view name);

common::PipelineCache createPipelineCache(const common::Device& device);

// The book's Pipeline: the layout (empty: no descriptors or push constants yet) and the pipeline.
struct Pipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline handle = VK_NULL_HANDLE;
};

Pipeline createPipeline(const common::Device& device, VkPipelineCache cache, VkRenderPass renderPass,
                        const VertexInput& vertexInput, VkFormat targetFormat);
void destroyPipeline(const common::Device& device, Pipeline& pipeline);
