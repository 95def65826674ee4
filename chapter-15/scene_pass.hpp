// chapter-15: the scene pass -- the scene into the book's PBR G-buffer: world position, albedo,
// normal (with normal maps) and PBR data (AO, roughness, metallic), all R16G16B16A16_SFLOAT,
// plus D32_SFLOAT depth: 36 bytes per pixel. The book's ScnRender and MrtAttachments.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.hpp"
#include "common/device.hpp"
#include "common/gbuffer.hpp"
#include "common/gpu_scene.hpp"

//> gbuffer-layouts
// The G-buffer layouts of --gbuffer. Attachment order = the fragment shader's output locations =
// the light pass's bindings (then depth, always D32_SFLOAT).
enum class GBufferLayout {
    Book,       // the book's: position, albedo, normal, AO/roughness/metallic, all RGBA16F (36 B/px)
    Reference,  // the same in RGBA32F: the accuracy yardstick (68 B/px)
    Compact,    // albedo 3 x 10 bits (gamma 2) + coverage, normal octahedral 2 x 16 bits,
                // roughness and metallic 2 x 16 bits; position from reversed-Z depth (16 B/px)
};

inline std::vector<VkFormat> gbufferColorFormats(GBufferLayout layout) {
    switch (layout) {
        case GBufferLayout::Reference:
            return std::vector<VkFormat>(4, VK_FORMAT_R32G32B32A32_SFLOAT);
        case GBufferLayout::Compact:
            return {VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_R16G16_UNORM, VK_FORMAT_R16G16_UNORM};
        default:
            return std::vector<VkFormat>(4, VK_FORMAT_R16G16B16A16_SFLOAT);
    }
}
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline bool reversedZ(GBufferLayout layout) {
    return layout == GBufferLayout::Compact;
}

// Bytes per pixel of the colour attachments and D32_SFLOAT depth.
inline uint32_t gbufferBytesPerPixel(GBufferLayout layout) {
    uint32_t bytes = 4;  // depth
    for (VkFormat format : gbufferColorFormats(layout))
        bytes += format == VK_FORMAT_R32G32B32A32_SFLOAT   ? 16
                 : format == VK_FORMAT_R16G16B16A16_SFLOAT ? 8
                                                           : 4;  // the 32-bit formats of the compact layout
    return bytes;
}
//< gbuffer-layouts

struct ScenePass {
    GBufferLayout layout = GBufferLayout::Book;
    common::GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout texturesLayout = VK_NULL_HANDLE;   // set 2: one per material, its 3 textures
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::Buffer> cameras;
    std::vector<VkDescriptorSet> cameraSets;
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialTextureSets;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline opaquePipeline = VK_NULL_HANDLE;  // no alpha test: early depth testing
    VkPipeline cutoutPipeline = VK_NULL_HANDLE;  // alpha-tested materials
};

// Throws Failure when the device cannot render to the layout's formats.
ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight, GBufferLayout layout);
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
// Opaque draws nearest first (so hidden fragments fail the depth test before shading), then cut-outs.
void recordScenePass(VkCommandBuffer cmd, const ScenePass& pass, const common::GpuScene& scene,
                     uint32_t frame, glm::vec3 cameraPosition);
void destroyScenePass(const common::Device& device, ScenePass& pass);
