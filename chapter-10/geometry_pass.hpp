// chapter-10: the geometry pass -- the scene rendered into the G-buffer (albedo + depth) with a
// classic VkRenderPass and VkFramebuffer. The book's GeometryAttachments, GeometryRenderPass,
// GeometryFrameBuffer and GeometryRenderActivity.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include <glm/glm.hpp>

#include "common/scene/gpu_scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/pipeline.hpp"

// The G-buffer: one set of attachments shared by all frames in flight (the subpass
// dependencies keep one frame's writes from overtaking the previous frame's reads).
struct GBuffer {
    common::Image albedo;  // R16G16B16A16_SFLOAT
    common::Image depth;   // D32_SFLOAT, or X8_D24_UNORM_PACK32 where the device lacks it
};

// The view matrix of one frame in flight: a host-visible uniform buffer written every frame (the
// camera moves), and the descriptor set (set 1) that binds it.
struct ViewFrame {
    common::Buffer buffer;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// A material as geometry.frag reads it (std140): the colour, and the alpha below which a texel
// is discarded (0: never).
struct GeometryMaterial {
    glm::vec4 diffuse;
    float alphaCutoff;
    float padding[3];
};

// A material class: what a geometry pipeline is specialised for (geometry.frag's constants).
struct MaterialClass {
    bool alphaTest = true;     // a cut-out
    bool baseColorMap = true;  // has a texture
    bool operator==(const MaterialClass&) const = default;
};

struct GeometryPass {
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    GBuffer gbuffer;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;

    // Set 0: projection, set 1: view (one per frame in flight), set 2: one per material (its
    // albedo texture), set 3: all materials in one dynamic uniform buffer.
    VkDescriptorSetLayout matrixLayout = VK_NULL_HANDLE;
    VkDescriptorSetLayout textureLayout = VK_NULL_HANDLE;
    VkDescriptorSetLayout materialLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    common::Buffer projection;
    std::vector<ViewFrame> views;  // per frame in flight
    common::Buffer materials;
    VkDeviceSize materialStride =
        0;  // sizeof(GeometryMaterial) rounded up to minUniformBufferOffsetAlignment
    VkDescriptorSet projectionSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> textureSets;
    VkDescriptorSet materialSet = VK_NULL_HANDLE;

    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    common::MaterialClasses<MaterialClass> materialClasses;  // the classes, and each material's
    std::vector<VkPipeline> pipelines;                       // one per class
};

// `generic` (--pipelines generic): one pipeline, with the alpha test and the texture, for every
// material; otherwise one per material class the scene has.
GeometryPass createGeometryPass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                                const common::GpuScene& scene, uint32_t framesInFlight, bool generic = false);
// New attachments and framebuffer at the new size; the render pass and pipelines stay.
void resizeGeometryPass(const common::Device& device, GeometryPass& pass, VkExtent2D extent);
void setProjection(GeometryPass& pass, const glm::mat4& projection);
void setView(GeometryPass& pass, uint32_t frame, const glm::mat4& view);
void recordGeometryPass(VkCommandBuffer cmd, const GeometryPass& pass, const common::GpuScene& scene,
                        uint32_t frame);
// Live reload: new pipelines into `swap` when the reload changed geometry.vert or geometry.frag.
void remakeGeometryPipeline(const common::Device& device, VkPipelineCache cache, GeometryPass& pass,
                            const common::ShaderReload& reload, common::PipelineSwap& swap);
void destroyGeometryPass(const common::Device& device, GeometryPass& pass);
