// chapter-15-lab: light ranges and tiled light culling.
#include "light_culling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "chapter-15/light_pass.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/pipeline.hpp"

namespace {

// --NAME VALUE as a number within [min, max], or nothing when the option is not given.
std::optional<float> numberOption(const common::Options& options, const std::string& name, float min,
                                  float max, const char* what) {
    auto given = options.values.find(name);
    if (given == options.values.end()) return std::nullopt;
    const std::string& text = given->second;
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value < min || value > max)
        throw common::InputError("--" + name + " must be " + what + ", got '" + text + "'");
    return float(value);
}

}  // namespace

LightOptions readLightOptions(const common::Options& options, common::Scene& scene) {
    LightOptions result;
    auto culling = options.choices.find("light-culling");
    result.culling = culling == options.choices.end() ? LightCulling::None : LightCulling(culling->second);
    result.orbitDegrees =
        numberOption(options, "orbit", -360.0f, 360.0f, "a number of degrees within -360..360")
            .value_or(0.0f);
    // The smallest positive normal float and 1e30: outside, a range would be infinite or zero.
    if (std::optional<float> cutoff =
            numberOption(options, "light-cutoff", 1.2e-38f, 1e30f, "a positive number (an irradiance)")) {
        size_t ranged = applyLightCutoff(scene, *cutoff);
        std::printf("chapter-15-lab: --light-cutoff %g: %zu point lights get a range\n", double(*cutoff),
                    ranged);
    }
    return result;
}

uint32_t boundedLightCount(const common::Scene& scene) {
    uint32_t count = 0;
    for (const common::Light& light : scene.lights)
        count += light.type == common::Light::Type::Point && light.range > 0.0f ? 1u : 0u;
    return count;
}

//> light-cutoff
size_t applyLightCutoff(common::Scene& scene, float cutoff) {
    size_t ranged = 0;
    for (common::Light& light : scene.lights) {
        if (light.type != common::Light::Type::Point || light.range > 0.0f) continue;
        // Irradiance at distance d, facing the light: intensity x colour / d^2 (the brightest
        // channel decides). Where it falls to the cutoff, the light ends. A black light reaches
        // nowhere; a tiny positive range keeps range 0's meaning ("unbounded") out of reach.
        double radiance =
            double(light.intensity) * double(std::max({light.color.r, light.color.g, light.color.b}));
        light.range = float(std::max(std::sqrt(radiance / double(cutoff)), 1e-6));
        ++ranged;
    }
    return ranged;
}
//< light-cutoff

uint32_t putUnboundedFirst(std::vector<ShaderLight>& lights) {
    auto unbounded = [](const ShaderLight& light) {
        return light.directional != 0u || !(light.range > 0.0f);
    };
    auto end = std::stable_partition(lights.begin(), lights.end(), unbounded);
    return uint32_t(end - lights.begin());
}

namespace {

constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// Buffers that follow the tile grid: sized from the window and the scene's lights.
void createTileBuffers(const common::Device& device, LightCullingPass& c, VkExtent2D extent) {
    c.extent = extent;
    c.tiles = {(extent.width + kLightTileSize - 1) / kLightTileSize,
               (extent.height + kLightTileSize - 1) / kLightTileSize};
    uint64_t tiles = uint64_t(c.tiles.x) * c.tiles.y;
    // Room for 64 lights per tile on average, and 4 tiles per light: what scenes with a few to a
    // few tens of lights per pixel need (at 65,536 lights of the generated scenes, 13 per tile).
    // A tile whose list does not fit is not dropped: it is shaded with every light.
    uint64_t wanted = tiles * 64 + uint64_t(c.boundedLights) * 4;
    uint64_t limit = std::min<uint64_t>(device.properties.limits.maxStorageBufferRange / 4, 1u << 28);
    c.capacity = uint32_t(std::clamp<uint64_t>(wanted, 1, limit));
    VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    c.tileBounds = common::createBuffer(device, tiles * 2 * sizeof(glm::vec4), storage,
                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "cull: tile bounds");
    c.tileCounts = common::createBuffer(device, tiles * sizeof(uint32_t), storage,
                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "cull: tile counts");
    c.tileLists = common::createBuffer(device, tiles * sizeof(glm::uvec2), storage,
                                       VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "cull: tile lists");
    c.indices = common::createBuffer(device, uint64_t(c.capacity) * sizeof(uint32_t), storage,
                                     VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "cull: light indices");
    for (LightCullingFrame& frame : c.frames) {
        const common::Buffer* buffers[] = {&c.tileBounds, &c.tileCounts, &c.tileLists,
                                           &c.indices,    &c.stats,      &c.large};
        for (uint32_t binding = 1; binding <= 6; ++binding)
            common::writeBufferDescriptor(device, frame.set, binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                          buffers[binding - 1]->handle, VK_WHOLE_SIZE);
    }
}

void destroyTileBuffers(const common::Device& device, LightCullingPass& c) {
    common::destroyBuffer(device, c.indices);
    common::destroyBuffer(device, c.tileLists);
    common::destroyBuffer(device, c.tileCounts);
    common::destroyBuffer(device, c.tileBounds);
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                             .srcStageMask = srcStage,
                             .srcAccessMask = srcAccess,
                             .dstStageMask = dstStage,
                             .dstAccessMask = dstAccess};
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1, .pMemoryBarriers = &barrier};
    common::vk13.CmdPipelineBarrier2(cmd, &dependency);
}

VkPipeline createComputePipeline(const common::Device& device, VkPipelineCache cache, VkPipelineLayout layout,
                                 const std::string& shader,
                                 const VkSpecializationInfo* specialization = nullptr) {
    common::ShaderModule module(device, shader);
    VkComputePipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module, specialization),
        .layout = layout};
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device.handle, cache, 1, &info, nullptr, &pipeline));
    common::nameObject(device.handle, pipeline, std::string(shader));
    return pipeline;
}

const char* const kCullShader = "chapter-15-lab/light_cull.comp";
const char* const kScanShader = "chapter-15-lab/light_cull_scan.comp";

// light_cull.comp with its FILL and LARGE constants.
VkPipeline createCullPipeline(const common::Device& device, VkPipelineCache cache, VkPipelineLayout layout,
                              bool fill, bool large) {
    VkBool32 constants[2] = {fill ? VK_TRUE : VK_FALSE, large ? VK_TRUE : VK_FALSE};
    VkSpecializationMapEntry entries[] = {{0, 0, sizeof(VkBool32)}, {1, sizeof(VkBool32), sizeof(VkBool32)}};
    VkSpecializationInfo specialization{2, entries, sizeof(constants), constants};
    return createComputePipeline(device, cache, layout, kCullShader, &specialization);
}

}  // namespace

LightCullingPass createLightCulling(const common::Device& device, VkExtent2D extent, uint32_t framesInFlight,
                                    uint32_t boundedLights, const GBufferLayout& layout, glm::vec3 boundsMin,
                                    glm::vec3 boundsMax) {
    LightCullingPass c;
    c.boundedLights = boundedLights;
    // A stored position is where the shading puts the surface, and the culling must agree with
    // it; a tile's box is made of those positions, so only a light's screen rectangle needs a
    // margin: fp16 positions (the book's layout) round by up to 2^-11 of each world coordinate,
    // so a pixel's position may lie up to sqrt(3) x 2^-11 x |largest coordinate| off its ray.
    // fp32 and reconstructed positions lie on the ray up to rounding (the shader's 1e-5 slack).
    glm::vec3 reach = glm::max(glm::abs(boundsMin), glm::abs(boundsMax));
    float largest = std::max({reach.x, reach.y, reach.z});
    c.margin = layout.formats.position == VK_FORMAT_R16G16B16A16_SFLOAT ? largest * 1.7321f / 2048.0f : 0.0f;

    c.setLayout =
        common::createDescriptorSetLayout(device,
                                          {common::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kStages),
                                           common::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages),
                                           common::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages),
                                           common::binding(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages),
                                           common::binding(4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages),
                                           common::binding(5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages),
                                           common::binding(6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStages)},
                                          "cull: lists");
    c.descriptorPool = common::createDescriptorPool(device, framesInFlight,
                                                    {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight},
                                                     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 6 * framesInFlight}},
                                                    "cull");
    VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    c.stats = common::createBuffer(device, 4 * sizeof(uint32_t),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   hostVisible, "cull: stats");
    // A VkDispatchIndirectCommand (16 bytes with the std430 padding), then one index per light.
    c.large = common::createBuffer(device, 16 + uint64_t(std::max(boundedLights, 1u)) * sizeof(uint32_t),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "cull: large lights");
    c.frames.resize(framesInFlight);
    for (LightCullingFrame& frame : c.frames) {
        frame.view = common::createBuffer(device, sizeof(CullView), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                          hostVisible, "cull: view");
        frame.set = common::allocateDescriptorSet(device, c.descriptorPool, c.setLayout, "cull");
        common::writeBufferDescriptor(device, frame.set, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      frame.view.handle, sizeof(CullView));
    }
    createTileBuffers(device, c, extent);
    return c;
}

void createLightCullingPipelines(const common::Device& device, VkPipelineCache cache, LightCullingPass& c,
                                 const LightPass& lightPass, const std::string& boundsShader) {
    VkDescriptorSetLayout setLayouts[] = {lightPass.attachmentsLayout, lightPass.lightsLayout,
                                          lightPass.sceneLayout, c.setLayout};
    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView)};
    c.pipelineLayout = common::createPipelineLayout(device, setLayouts, {&push, 1}, "cull");
    c.boundsShader = boundsShader;
    c.bounds = createComputePipeline(device, cache, c.pipelineLayout, boundsShader);
    c.count = createCullPipeline(device, cache, c.pipelineLayout, false, false);
    c.countLarge = createCullPipeline(device, cache, c.pipelineLayout, false, true);
    c.fill = createCullPipeline(device, cache, c.pipelineLayout, true, false);
    c.fillLarge = createCullPipeline(device, cache, c.pipelineLayout, true, true);
    c.scan = createComputePipeline(device, cache, c.pipelineLayout, kScanShader);
}

void remakeLightCullingPipelines(const common::Device& device, VkPipelineCache cache, LightCullingPass& c,
                                 const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (c.pipelineLayout == VK_NULL_HANDLE) return;
    VkPipelineLayout layout = c.pipelineLayout;
    if (reload.changed({c.boundsShader}))
        common::replacePipeline(swap, c.bounds,
                                [&] { return createComputePipeline(device, cache, layout, c.boundsShader); });
    if (reload.changed({kCullShader})) {
        common::replacePipeline(swap, c.count,
                                [&] { return createCullPipeline(device, cache, layout, false, false); });
        common::replacePipeline(swap, c.countLarge,
                                [&] { return createCullPipeline(device, cache, layout, false, true); });
        common::replacePipeline(swap, c.fill,
                                [&] { return createCullPipeline(device, cache, layout, true, false); });
        common::replacePipeline(swap, c.fillLarge,
                                [&] { return createCullPipeline(device, cache, layout, true, true); });
    }
    if (reload.changed({kScanShader}))
        common::replacePipeline(swap, c.scan,
                                [&] { return createComputePipeline(device, cache, layout, kScanShader); });
}

void resizeLightCulling(const common::Device& device, LightCullingPass& c, VkExtent2D extent) {
    destroyTileBuffers(device, c);
    createTileBuffers(device, c, extent);
}

void updateLightCulling(LightCullingPass& c, uint32_t frame, const glm::mat4& viewRotation,
                        const glm::mat4& projection, float near, uint32_t unboundedLights) {
    CullView view{.viewRotation = viewRotation,
                  .projectionScale = {projection[0][0], projection[1][1]},
                  .near = near,
                  .margin = c.margin,
                  .tileCount = c.tiles,
                  .extent = {c.extent.width, c.extent.height},
                  .capacity = c.capacity,
                  .unboundedLights = unboundedLights};
    std::memcpy(c.frames[frame].view.mapped, &view, sizeof(view));
}

//> record-culling
void recordLightCulling(VkCommandBuffer cmd, const LightCullingPass& c, const LightPass& lightPass,
                        uint32_t frame, const LightView& view) {
    constexpr VkPipelineStageFlags2 compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    constexpr VkAccessFlags2 readWrite =
        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    constexpr VkPipelineStageFlags2 indirect = VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT;
    // The previous frame's passes (culling, its indirect dispatches, the light pass) are done with
    // the buffers before this frame clears the counts and rebuilds the lists.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | compute | indirect,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT | compute,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT | readWrite);
    vkCmdFillBuffer(cmd, c.tileCounts.handle, 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, c.stats.handle, 0, VK_WHOLE_SIZE, 0);
    const uint32_t noLargeLights[3] = {0, 1, 1};  // groups x, y, z of the large lights' dispatches
    vkCmdUpdateBuffer(cmd, c.large.handle, 0, sizeof(noLargeLights), noLargeLights);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, compute, readWrite);

    VkDescriptorSet sets[] = {lightPass.attachmentsSet, lightPass.frames[frame].lightsSet,
                              lightPass.frames[frame].sceneSet, c.frames[frame].set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.pipelineLayout, 0, 4, sets, 0, nullptr);
    vkCmdPushConstants(cmd, c.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(LightView), &view);
    uint32_t lightGroups = (c.boundedLights + 63) / 64;

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.bounds);  // each tile's box
    vkCmdDispatch(cmd, c.tiles.x, c.tiles.y, 1);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute, readWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.count);  // lights per tile
    if (lightGroups > 0) vkCmdDispatch(cmd, lightGroups, 1, 1);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute | indirect,
                  readWrite | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.countLarge);  // ... of the large lights
    vkCmdDispatchIndirect(cmd, c.large.handle, 0);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute, readWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.scan);  // counts to offsets
    vkCmdDispatch(cmd, 1, 1, 1);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute, readWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.fill);  // the lists
    if (lightGroups > 0) vkCmdDispatch(cmd, lightGroups, 1, 1);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute | indirect,
                  readWrite | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.fillLarge);  // ... of the large lights
    vkCmdDispatchIndirect(cmd, c.large.handle, 0);
    // The lists to the light pass (either form); the statistics to the host after the fence.
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | compute | VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_HOST_READ_BIT);
}
//< record-culling

LightCullingStats readLightCullingStats(const LightCullingPass& c) {
    LightCullingStats stats;
    std::memcpy(&stats, c.stats.mapped, sizeof(stats));
    return stats;
}

void reportLightCulling(const LightCullingPass& c) {
    LightCullingStats stats = readLightCullingStats(c);
    std::printf(
        "chapter-15-lab: light culling: %u light-tile pairs, %u of %u tiles lit, at most %u lights in a "
        "tile, "
        "%u tiles over capacity (%u indices)\n",
        stats.pairs, stats.litTiles, c.tiles.x * c.tiles.y, stats.maxTileLights, stats.overflowTiles,
        c.capacity);
}

void destroyLightCulling(const common::Device& device, LightCullingPass& c) {
    for (VkPipeline pipeline : {c.bounds, c.count, c.countLarge, c.scan, c.fill, c.fillLarge})
        vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, c.pipelineLayout, nullptr);
    destroyTileBuffers(device, c);
    common::destroyBuffer(device, c.stats);
    common::destroyBuffer(device, c.large);
    for (LightCullingFrame& frame : c.frames) common::destroyBuffer(device, frame.view);
    vkDestroyDescriptorPool(device.handle, c.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, c.setLayout, nullptr);
    c = {};
}
