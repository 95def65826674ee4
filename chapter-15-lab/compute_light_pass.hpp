// chapter-15-lab: the light pass as a compute dispatch (--light-pass compute). The same shading
// (light_shading.glsl) and the same descriptor sets 0-2 and push constants as chapter-15's
// full-screen triangle -- the LightPass made with the compute stage and a storage-image output,
// and no pipeline of its own -- plus set 3: the output as a storage image (and set 4, the tile
// lists, with --light-culling tiled).
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "chapter-15/light_pass.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

// How the light pass runs: chapter-15's full-screen triangle, or a compute dispatch.
enum class LightPassKind { Fragment, Compute };

struct ComputeLightPass {
    VkDescriptorSetLayout outputLayout = VK_NULL_HANDLE;  // set 3: the output as a storage image
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet outputSet = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::string shader;  // what the pipeline is made from
    bool tiled = false;  // set 4: the tile lists
    LightKinds kinds;    // what the pipeline is specialised to (the light pass's)
};

// The setup of a LightPass for the compute form: sets 0-2 read by compute (and by `alsoStages`).
LightPassSetup computeLightPassSetup(VkShaderStageFlags alsoStages = 0);
// `shader`: the compiled compute shader; `tileLists`: --light-culling tiled's set layout, else null.
ComputeLightPass createComputeLightPass(const common::Device& device, VkPipelineCache cache,
                                        const LightPass& lightPass, const std::string& shader,
                                        VkDescriptorSetLayout tileLists);
// Points set 3 at the light pass's (new) output image.
void writeComputeOutput(const common::Device& device, const ComputeLightPass& pass,
                        const LightPass& lightPass);
// `tileLists`: --light-culling tiled's set, else VK_NULL_HANDLE.
void recordComputeLightPass(VkCommandBuffer cmd, const ComputeLightPass& pass, const LightPass& lightPass,
                            uint32_t frame, const LightView& view, VkDescriptorSet tileLists);
// Live reload: a new pipeline into `swap` when the reload changed the pass's shader.
void remakeComputeLightPipeline(const common::Device& device, VkPipelineCache cache, ComputeLightPass& pass,
                                const common::ShaderReload& reload, common::PipelineSwap& swap);
void destroyComputeLightPass(const common::Device& device, ComputeLightPass& pass);
