// chapter-15, beyond the book: the light pass as a compute dispatch (--light-pass compute). The
// same shading (light_shading.glsl) and the same descriptor sets 0-2 and push constants as the
// book's full-screen triangle, plus set 3: the output as a storage image (and set 4, the tile
// lists, with --light-culling tiled).
#pragma once

#include <vulkan/vulkan.h>

#include "common/device.hpp"
#include "gbuffer_layout.hpp"
#include "light_pass.hpp"

// The storage-image set and the compute pipeline; `pass.descriptorPool` has room for the set.
void createComputeLightPipeline(const common::Device& device, VkPipelineCache cache, LightPass& pass,
                                const GBufferLayout& layout);
// Points set 3 at the (new) output image.
void writeComputeOutput(const common::Device& device, LightPass& pass);
// `tileLists`: --light-culling tiled's set (4), else VK_NULL_HANDLE.
void recordComputeLightPass(VkCommandBuffer cmd, const LightPass& pass, uint32_t frame, const LightView& view,
                            VkDescriptorSet tileLists);
void destroyComputeLightPipeline(const common::Device& device, LightPass& pass);
