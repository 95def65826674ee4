// Test helper: one compute dispatch.
#include "gpu_compute.hpp"

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/pipeline.hpp"

void runCompute(const common::Device& device, const std::filesystem::path& spirv,
                const std::vector<ComputeBinding>& bindings, const void* push, uint32_t pushSize,
                uint32_t groups) {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    uint32_t storage = 0, uniform = 0;
    for (uint32_t i = 0; i < bindings.size(); ++i) {
        layoutBindings.push_back(common::binding(i, bindings[i].type, VK_SHADER_STAGE_COMPUTE_BIT));
        (bindings[i].type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER ? uniform : storage) += 1;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                            .bindingCount = uint32_t(layoutBindings.size()),
                                            .pBindings = layoutBindings.data()};
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(device.handle, &setInfo, nullptr, &setLayout));
    VkDescriptorPool pool = common::createDescriptorPool(
        device, 1,
        {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storage}, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniform}},
        "compute");
    VkDescriptorSet set = common::allocateDescriptorSet(device, pool, setLayout, "gpu compute");
    for (uint32_t i = 0; i < bindings.size(); ++i)
        common::writeBufferDescriptor(device, set, i, bindings[i].type, bindings[i].buffer, VK_WHOLE_SIZE);

    std::vector<char> code = common::readFile(spirv);
    VkShaderModuleCreateInfo moduleInfo{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                        .codeSize = code.size(),
                                        .pCode = reinterpret_cast<const uint32_t*>(code.data())};
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.handle, &moduleInfo, nullptr, &module));
    VkPushConstantRange range{.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT, .offset = 0, .size = pushSize};
    VkPipelineLayout pipelineLayout =
        common::createPipelineLayout(device, {&setLayout, 1}, {&range, pushSize ? 1u : 0u}, "compute test");
    VkComputePipelineCreateInfo pipelineInfo{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                  .module = module,
                  .pName = "main"},
        .layout = pipelineLayout,
    };
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device.handle, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline));

    VkCommandBuffer cmd = common::beginOneTimeCommands(device);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout, 0, 1, &set, 0, nullptr);
    if (pushSize) vkCmdPushConstants(cmd, pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushSize, push);
    vkCmdDispatch(cmd, groups, 1, 1);
    VkMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                           .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                           .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                         0, nullptr, 0, nullptr);
    common::submitOneTimeCommands(device, cmd);

    vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pipelineLayout, nullptr);
    vkDestroyShaderModule(device.handle, module, nullptr);
    vkDestroyDescriptorPool(device.handle, pool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, setLayout, nullptr);
}
