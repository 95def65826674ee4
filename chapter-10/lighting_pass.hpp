// chapter-10: the lighting pass -- a full-screen triangle drawn into the target image, sampling
// the G-buffer. Its command buffers are recorded once per target image and only re-recorded when
// something they contain changes (a resize, another --view). The book's LightingRenderPass,
// LightingFrameBuffer, AttachmentsLayout, AttachmentsDescriptorSet and LightingRenderActivity.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>

#include <vector>

#include "common/vk/device.hpp"
#include "common/wnd/target.hpp"
#include "geometry_pass.hpp"

// What the lighting pass shows (a push constant recorded into its command buffers).
// The twin of lighting.frag's LightingView push-constant block (std430: three 4-byte scalars; the
// --view depth golden images would show a mismatch of near or far).
struct LightingView {
    int view = 0;  // index into the chapter's --view names
    float near = 0.1f;
    float far = 100.0f;
};
static_assert(sizeof(LightingView) == 12 && offsetof(LightingView, near) == 4 &&
              offsetof(LightingView, far) == 8);

struct LightingPass {
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkFormat targetFormat = VK_FORMAT_UNDEFINED;  // what the render pass and the pipeline were made for
    std::vector<VkFramebuffer> framebuffers;      // one per target image
    VkDescriptorSetLayout attachmentsLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet attachmentsSet = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    std::vector<VkCommandBuffer> commandBuffers;  // one per target image, pre-recorded
};

LightingPass createLightingPass(const common::Device& device, VkPipelineCache cache,
                                const common::Target& target, const GBuffer& gbuffer);
// After a resize: new framebuffers for the new target images, the descriptor set pointed at the
// new G-buffer; and when the images' format changed (the window moved to a screen with other
// formats), a render pass and a pipeline for the new one. The device must be idle.
void resizeLightingPass(const common::Device& device, VkPipelineCache cache, LightingPass& pass,
                        const common::Target& target, const GBuffer& gbuffer);
// (Re-)records every target image's command buffer. The device must be idle.
// Live reload: a new pipeline into `swap` when the reload changed lighting.vert or lighting.frag;
// true when so (the command buffers must be recorded again once it is in place).
bool remakeLightingPipeline(const common::Device& device, VkPipelineCache cache, LightingPass& pass,
                            const common::Target& target, const common::ShaderReload& reload,
                            common::PipelineSwap& swap);
void recordLightingPass(const common::Device& device, LightingPass& pass, const common::Target& target,
                        const LightingView& view);
void destroyLightingPass(const common::Device& device, LightingPass& pass);
