// chapter-06: shader modules, the pipeline cache and the graphics pipeline.
#include "pipeline.hpp"

#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/formats.hpp"
#include "shader_compiler.hpp"

//> shader-module
// The SPIR-V comes from the book's ShaderCompiler (shader_compiler.cpp): compiled now when the
// GLSL is newer than what the build compiled (glslangValidator, cmake/VulkanBook.cmake, so a
// shader error is still a build error), else the build's <executable's directory>/shaders/<name>.spv.
VkShaderModule createShaderModule(const common::Device& device, std::string_view name) {
    std::vector<uint32_t> code = compileShaderIfChanged(name);
    VkShaderModuleCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
        .codeSize = code.size() * sizeof(uint32_t),  // in bytes
        .pCode = code.data(),
    };
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.handle, &info, nullptr, &module));
    common::nameObject(device.handle, module, std::string(name));  // what a debugger calls it
    return module;
}
//< shader-module

//> pipeline-cache
// A pipeline cache lets the driver reuse the work of compiling pipelines: between the pipelines
// of one run and, when its bytes are saved (common::savePipelineCache at exit) and given back
// here, between runs. The book starts with an empty cache; we also keep it on disk, and
// common::readPipelineCacheFile returns no bytes when the file is missing, damaged or was
// written by another device or driver (its header says which).
common::PipelineCache createPipelineCache(const common::Device& device) {
    common::PipelineCacheFile file = common::readPipelineCacheFile(device, "chapter-06");
    common::PipelineCache cache{.file = file.path};
    VkPipelineCacheCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO,
        .initialDataSize = file.data.size(),  // 0: an empty cache
        .pInitialData = file.data.data(),
    };
    if (vkCreatePipelineCache(device.handle, &info, nullptr, &cache.handle) != VK_SUCCESS) {
        common::warn("the driver refused pipeline cache '" + common::utf8(file.path) + "'; starting empty");
        info.initialDataSize = 0;
        info.pInitialData = nullptr;
        VK_CHECK(vkCreatePipelineCache(device.handle, &info, nullptr, &cache.handle));
    }
    common::nameObject(device.handle, cache.handle, "pipeline cache chapter-06");
    return cache;
}
//< pipeline-cache

//> pipeline
Pipeline createPipeline(const common::Device& device, VkPipelineCache cache, VkRenderPass renderPass,
                        const VertexInput& vertexInput, VkFormat targetFormat) {
    // The programmable stages: the two shaders, each entered at main().
    VkShaderModule vertex = createShaderModule(device, "chapter-06/triangle.vert");
    VkShaderModule fragment = createShaderModule(device, "chapter-06/triangle.frag");
    // The fragment shader's one specialization constant (constant_id 0): whether it sRGB-encodes
    // its colour itself, because the target image's format does not (a _UNORM format, such as
    // the 10-bit one a 30-bit desktop offers). Fixed when the pipeline is made.
    VkBool32 encodeSrgb = common::encodesSrgb(targetFormat) ? VK_FALSE : VK_TRUE;
    VkSpecializationMapEntry encodeEntry{.constantID = 0, .offset = 0, .size = sizeof(VkBool32)};
    VkSpecializationInfo fragmentConstants{
        .mapEntryCount = 1,
        .pMapEntries = &encodeEntry,
        .dataSize = sizeof(encodeSrgb),
        .pData = &encodeSrgb,
    };
    VkPipelineShaderStageCreateInfo stages[] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_VERTEX_BIT,
         .module = vertex,
         .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = fragment,
         .pName = "main",
         .pSpecializationInfo = &fragmentConstants},
    };

    // Input assembly: every three indices make one triangle.
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
    };
    // One viewport and one scissor; their values are dynamic state, set while recording, so a
    // resized window does not need a new pipeline.
    VkPipelineViewportStateCreateInfo viewport{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
        .viewportCount = 1,
        .scissorCount = 1,
    };
    VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
        .dynamicStateCount = 2,
        .pDynamicStates = dynamicStates,
    };
    // Rasterization: filled triangles, both faces drawn (no culling yet).
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .polygonMode = VK_POLYGON_MODE_FILL,
        .cullMode = VK_CULL_MODE_NONE,
        .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
        .lineWidth = 1.0f,
    };
    // One sample per pixel: no multisampling.
    VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT,
    };
    // No depth attachment in this render pass, so no depth test.
    VkPipelineDepthStencilStateCreateInfo depthStencil{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
    };
    // Blending: off; the fragment's colour replaces the pixel's, all four channels written.
    VkPipelineColorBlendAttachmentState blendAttachment{
        .blendEnable = VK_FALSE,
        .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                          VK_COLOR_COMPONENT_A_BIT,
    };
    VkPipelineColorBlendStateCreateInfo colorBlend{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
        .attachmentCount = 1,  // one per colour attachment of the subpass
        .pAttachments = &blendAttachment,
    };

    // The pipeline layout says which descriptor sets and push constants the shaders use: none yet.
    Pipeline pipeline;
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreatePipelineLayout(device.handle, &layoutInfo, nullptr, &pipeline.layout));
    common::nameObject(device.handle, pipeline.layout, "triangle");

    VkGraphicsPipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
        .stageCount = 2,
        .pStages = stages,
        .pVertexInputState = &vertexInput.state,
        .pInputAssemblyState = &inputAssembly,
        .pViewportState = &viewport,
        .pRasterizationState = &rasterization,
        .pMultisampleState = &multisample,
        .pDepthStencilState = &depthStencil,
        .pColorBlendState = &colorBlend,
        .pDynamicState = &dynamic,
        .layout = pipeline.layout,
        .renderPass = renderPass,  // the pipeline renders in subpass 0 of this render pass
        .subpass = 0,
    };
    VkResult result = vkCreateGraphicsPipelines(device.handle, cache, 1, &info, nullptr, &pipeline.handle);

    // The pipeline keeps what it needs; the modules can go. If it could not be made, the layout
    // goes too (a failed live reload leaves nothing behind).
    vkDestroyShaderModule(device.handle, fragment, nullptr);
    vkDestroyShaderModule(device.handle, vertex, nullptr);
    if (result != VK_SUCCESS) vkDestroyPipelineLayout(device.handle, pipeline.layout, nullptr);
    VK_CHECK_RESULT(result, "vkCreateGraphicsPipelines");
    common::nameObject(device.handle, pipeline.handle, "triangle");
    return pipeline;
}
//< pipeline

void destroyPipeline(const common::Device& device, Pipeline& pipeline) {
    vkDestroyPipeline(device.handle, pipeline.handle, nullptr);
    vkDestroyPipelineLayout(device.handle, pipeline.layout, nullptr);
    pipeline = {};
}
