// Pipeline cache persistence and graphics pipeline creation.
#include "common/vk/pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

// Why `data` cannot seed a pipeline cache on this device; empty when it can. The layout is
// VkPipelineCacheHeaderVersionOne (Vulkan spec, "Pipeline Cache"): drivers reject a foreign
// cache themselves, but not all of them do it gracefully, so we check first.
std::string cacheMismatch(const Device& device, const std::vector<char>& data) {
    VkPipelineCacheHeaderVersionOne header;
    if (data.size() < sizeof(header)) return "it is shorter than a cache header";
    std::memcpy(&header, data.data(), sizeof(header));
    if (header.headerSize < sizeof(header) || header.headerSize > data.size())
        return "its header size is wrong";
    if (header.headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE) return "its header version is unknown";
    if (header.vendorID != device.properties.vendorID || header.deviceID != device.properties.deviceID ||
        std::memcmp(header.pipelineCacheUUID, device.properties.pipelineCacheUUID, VK_UUID_SIZE) != 0)
        return "it was written by another device or driver";
    return {};
}

}  // namespace

PipelineCacheFile readPipelineCacheFile(const Device& device, std::string_view name) {
    PipelineCacheFile file;
    if (std::filesystem::path dir = cacheDir(); !dir.empty()) {
        char suffix[32];
        std::snprintf(suffix, sizeof(suffix), "-%04x-%04x.bin", device.properties.vendorID,
                      device.properties.deviceID);
        file.path = dir / (std::string(name) + suffix);
    }

    std::error_code ec;
    if (!file.path.empty() && std::filesystem::exists(file.path, ec)) {
        // On Windows another run of the same chapter may be replacing the file this moment (the
        // rename in savePipelineCache), and the file cannot be opened meanwhile. That lasts
        // milliseconds: a failed read is tried again a few times, as the rename is.
        std::string why;
        for (int attempt = 0; attempt < 20; ++attempt) {
            try {
                file.data = readFile(file.path);
                why = cacheMismatch(device, file.data);
                break;
            } catch (const Failure& error) {
                why = error.what();
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
        }
        if (!why.empty()) {
            warn("ignoring pipeline cache '" + utf8(file.path) + "': " + why);
            file.data.clear();
        }
    }
    return file;
}

PipelineCache loadPipelineCache(const Device& device, std::string_view name) {
    PipelineCacheFile file = readPipelineCacheFile(device, name);
    PipelineCache cache{.file = file.path};
    VkPipelineCacheCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO,
        .initialDataSize = file.data.size(),
        .pInitialData = file.data.data(),
    };
    if (vkCreatePipelineCache(device.handle, &info, nullptr, &cache.handle) != VK_SUCCESS) {
        warn("the driver refused pipeline cache '" + utf8(cache.file) + "'; starting empty");
        info.initialDataSize = 0;
        info.pInitialData = nullptr;
        VK_CHECK(vkCreatePipelineCache(device.handle, &info, nullptr, &cache.handle));
    }
    nameObject(device.handle, cache.handle, "pipeline cache " + std::string(name));
    return cache;
}

void savePipelineCache(const Device& device, const PipelineCache& cache) {
    if (cache.file.empty()) return;
    size_t size = 0;
    VK_CHECK(vkGetPipelineCacheData(device.handle, cache.handle, &size, nullptr));
    std::vector<char> data(size);
    VK_CHECK(vkGetPipelineCacheData(device.handle, cache.handle, &size, data.data()));
    data.resize(size);

    // A crash or a second process halfway through never leaves a truncated cache behind: the
    // bytes go to a file of our own first, which then replaces the old one in one rename().
    std::error_code ec;
    std::filesystem::create_directories(cache.file.parent_path(), ec);
    removeStaleTemporaries(cache.file);
    RegisteredTemporary written(cache.file);  // removed by a run cut short (run_control.hpp)
    const std::filesystem::path& temporary = written.path;
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(data.data(), static_cast<std::streamsize>(data.size()));
        if (!out.flush()) {
            warn("cannot write pipeline cache '" + utf8(temporary) + "'");
            std::filesystem::remove(temporary, ec);
            return;
        }
    }
    // On Windows a file cannot be replaced while another process has it open: a second run of
    // the same chapter may be reading the cache right now. That lasts milliseconds; try again a
    // few times before giving up (on Linux and macOS the first rename succeeds).
    for (int attempt = 0; attempt < 20; ++attempt) {
        std::filesystem::rename(temporary, cache.file, ec);
        if (!ec) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (ec) {
        warn("cannot write pipeline cache '" + utf8(cache.file) + "': " + ec.message());
        std::filesystem::remove(temporary, ec);
    }
}

void destroyPipelineCache(const Device& device, PipelineCache& cache) {
    vkDestroyPipelineCache(device.handle, cache.handle, nullptr);
    cache = {};
}

VkPipelineLayout createPipelineLayout(const Device& device, std::span<const VkDescriptorSetLayout> sets,
                                      std::span<const VkPushConstantRange> pushConstants,
                                      const std::string& name) {
    VkPipelineLayoutCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = uint32_t(sets.size()),
        .pSetLayouts = sets.data(),
        .pushConstantRangeCount = uint32_t(pushConstants.size()),
        .pPushConstantRanges = pushConstants.data(),
    };
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(device.handle, &info, nullptr, &layout));
    nameObject(device.handle, layout, name);
    return layout;
}

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, VkShaderModule module,
                                            const VkSpecializationInfo* specialization) {
    return {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
        .stage = stage,
        .module = module,
        .pName = "main",
        .pSpecializationInfo = specialization,
    };
}

VkPipeline createGraphicsPipeline(const Device& device, VkPipelineCache cache,
                                  const GraphicsPipelineDesc& desc) {
    VkPipelineVertexInputStateCreateInfo noVertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = desc.topology,
    };
    // Counts only: the viewport and scissor themselves are dynamic state.
    VkPipelineViewportStateCreateInfo viewport{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
        .viewportCount = 1,
        .scissorCount = 1,
    };
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .polygonMode = VK_POLYGON_MODE_FILL,
        .cullMode = desc.cullMode,
        .frontFace = desc.frontFace,
        .lineWidth = 1.0f,
    };
    VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT,
    };
    VkPipelineDepthStencilStateCreateInfo depthStencil{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = desc.depthTest,
        .depthWriteEnable = desc.depthWrite,
        .depthCompareOp = desc.depthCompare,
    };
    std::vector<VkPipelineColorBlendAttachmentState> blendAttachments(
        desc.colorAttachmentCount, {.blendEnable = desc.alphaBlend ? VK_TRUE : VK_FALSE,
                                    .srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA,
                                    .dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
                                    .colorBlendOp = VK_BLEND_OP_ADD,
                                    .srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE,
                                    .dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
                                    .alphaBlendOp = VK_BLEND_OP_ADD,
                                    .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                      VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT});
    VkPipelineColorBlendStateCreateInfo colorBlend{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
        .attachmentCount = desc.colorAttachmentCount,
        .pAttachments = blendAttachments.data(),
    };
    VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
        .dynamicStateCount = 2,
        .pDynamicStates = dynamicStates,
    };
    VkGraphicsPipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
        .pNext = desc.pNext,
        .stageCount = static_cast<uint32_t>(desc.stages.size()),
        .pStages = desc.stages.data(),
        .pVertexInputState = desc.vertexInput ? desc.vertexInput : &noVertexInput,
        .pInputAssemblyState = &inputAssembly,
        .pViewportState = &viewport,
        .pRasterizationState = &rasterization,
        .pMultisampleState = &multisample,
        .pDepthStencilState = &depthStencil,
        .pColorBlendState = &colorBlend,
        .pDynamicState = &dynamic,
        .layout = desc.layout,
        .renderPass = desc.renderPass,
        .subpass = desc.subpass,
    };
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(device.handle, cache, 1, &info, nullptr, &pipeline));
    nameObject(device.handle, pipeline, desc.name);
    return pipeline;
}

void discardPipelines(const Device& device, PipelineSwap& swap) {
    for (auto& [place, made] : swap.pipelines) vkDestroyPipeline(device.handle, made, nullptr);
    swap = {};
}

void swapPipelines(Device& device, PipelineSwap& swap, uint64_t frame) {
    for (auto& [place, made] : swap.pipelines) {
        device.retiredPipelines.push_back({*place, frame});
        *place = made;
    }
    swap = {};
}

void releaseRetiredPipelines(Device& device, uint64_t frame, uint32_t framesInFlight) {
    // Frames up to frame - framesInFlight are complete (fences signal in submission order): a
    // pipeline retired before frame r was last used by frame r - 1.
    std::erase_if(device.retiredPipelines, [&](const Device::RetiredPipeline& retired) {
        bool done = retired.frame + framesInFlight <= frame + 1;
        if (done) vkDestroyPipeline(device.handle, retired.pipeline, nullptr);
        return done;
    });
}

}  // namespace common
