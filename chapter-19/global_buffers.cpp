// chapter-19: the book's GlobalBuffers (global_buffers.hpp).
#include "global_buffers.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <tuple>

#include "chapter-15/gpu_types.hpp"
#include "common/core/check.hpp"

namespace {

// Room for `bytes` in `growing`: a buffer outgrown is destroyed (the slot's last frame is done with
// it) and made again at twice what is needed, so that a scene that grows a little each frame does
// not make a buffer each frame. Nothing is made for 0 bytes.
void reserve(const common::Device& device, GrowingBuffer& growing, VkDeviceSize bytes,
             VkBufferUsageFlags usage, const std::string& name, uint64_t& grown) {
    if (bytes <= growing.capacity) return;
    if (growing.buffer.handle != VK_NULL_HANDLE) common::destroyBuffer(device, growing.buffer);
    growing.capacity = 0;
    VkDeviceSize capacity = std::max<VkDeviceSize>(bytes * 2, 4096);
    growing.buffer = common::createBuffer(
        device, capacity, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
        name);
    growing.capacity = capacity;
    ++grown;
}

constexpr VkBufferUsageFlags kAddressed =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

// vkCmdDrawIndirect for each group: its pipeline (when it changes) and its material's textures
// and index bound first; at most maxDrawIndirectCount commands a call.
void drawGroups(VkCommandBuffer cmd, const GlobalBuffers& buffers, const FrameBuffers& frame,
                const std::vector<IndirectGroup>& groups, VkPipelineLayout layout, const ScenePass& scenePass,
                const std::function<VkPipeline(const IndirectGroup&)>& pipelineOf, VkPipeline& bound,
                uint32_t& calls) {
    for (const IndirectGroup& group : groups) {
        VkPipeline pipeline = pipelineOf(group);
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1,
                                &scenePass.materialTextureSets[group.material], 0, nullptr);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, kIndirectMaterialOffset,
                           sizeof(uint32_t), &group.material);
        for (uint32_t first = 0; first < group.commandCount; first += buffers.maxDrawIndirectCount) {
            uint32_t count = std::min(buffers.maxDrawIndirectCount, group.commandCount - first);
            vkCmdDrawIndirect(cmd, frame.commands.buffer.handle,
                              VkDeviceSize(group.firstCommand + first) * sizeof(VkDrawIndirectCommand), count,
                              sizeof(VkDrawIndirectCommand));
            ++calls;
        }
    }
}

void pushAddresses(VkCommandBuffer cmd, VkPipelineLayout layout, const FrameBuffers& frame) {
    IndirectConstants constants{frame.instances.buffer.address, frame.matrices.buffer.address};
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(constants), &constants);
}

}  // namespace

std::vector<uint32_t> sceneDrawOrder(const common::GpuScene& scene, const std::vector<uint32_t>& classOf) {
    auto key = [&](uint32_t d) {
        const common::Draw& draw = scene.draws[d];
        return std::tuple(scene.materials[draw.material].alphaTested, classOf[draw.material], draw.material,
                          draw.mesh, d);
    };
    std::vector<uint32_t> order(scene.draws.size());
    for (uint32_t d = 0; d < order.size(); ++d) order[d] = d;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    return order;
}

//> append-commands
void appendCommands(const common::GpuScene& scene, const std::vector<std::pair<uint32_t, uint32_t>>& draws,
                    InstanceData* instances, uint32_t& instanceCount, VkDrawIndirectCommand* commands,
                    uint32_t& commandCount, std::vector<IndirectGroup>& groups) {
    uint32_t lastMesh = UINT32_MAX, lastMaterial = UINT32_MAX;
    for (const auto& [drawIndex, layers] : draws) {
        const common::Draw& draw = scene.draws[drawIndex];
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        if (draw.material != lastMaterial) {
            groups.push_back({draw.material, scene.materials[draw.material].alphaTested, commandCount, 0});
            lastMesh = UINT32_MAX;
        }
        if (draw.mesh != lastMesh) {
            // A vertex per index, pulled by the shader: vertexCount is the index count.
            commands[commandCount++] = {mesh.indexCount, 0, 0, instanceCount};
            ++groups.back().commandCount;
        }
        ++commands[commandCount - 1].instanceCount;
        instances[instanceCount++] = {drawIndex, layers, mesh.indices.address, mesh.vertices.address};
        lastMesh = draw.mesh;
        lastMaterial = draw.material;
    }
}
//< append-commands

GlobalBuffers createGlobalBuffers(const common::Device& device, uint32_t framesInFlight) {
    GlobalBuffers buffers;
    buffers.frames.resize(framesInFlight);
    // A device with multiDrawIndirect draws at least 65,535 commands a call.
    buffers.maxDrawIndirectCount = std::max(1u, device.properties.limits.maxDrawIndirectCount);
    return buffers;
}

//> update-buffers
void updateGlobalBuffers(const common::Device& device, GlobalBuffers& buffers, uint32_t slot,
                         const common::GpuScene& scene, const ScenePass& scenePass, uint64_t shadowDraws) {
    FrameBuffers& frame = buffers.frames[slot];
    const size_t draws = scene.draws.size();
    // The order the scene pass draws in (sceneDrawOrder), made once: draws keep their mesh and
    // material (only their matrices move).
    if (buffers.sceneOrder.size() != draws)
        buffers.sceneOrder = sceneDrawOrder(scene, scenePass.pipelines.materialClasses.ofMaterial);
    // Room for the scene's instances and commands and the shadow plan's; matrices for every draw.
    const uint64_t instances = draws + shadowDraws;
    if (instances > UINT32_MAX) throw common::Failure("more instances in a frame than 2^32");
    std::string name = "frame " + std::to_string(slot) + " ";
    reserve(device, frame.matrices, draws * sizeof(DrawConstants), kAddressed, name + "matrices",
            buffers.grown);
    reserve(device, frame.instances, instances * sizeof(InstanceData), kAddressed, name + "instances",
            buffers.grown);
    reserve(device, frame.commands, instances * sizeof(VkDrawIndirectCommand),
            VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, name + "draw commands", buffers.grown);
    frame.instanceCount = frame.commandCount = 0;
    buffers.sceneGroups.clear();
    buffers.shadowCommands = buffers.shadowInstances = buffers.shadowIndirectDraws = 0;
    if (draws == 0) return;  // nothing to draw: nothing made, nothing written

    // Every draw's matrices, where this frame has put them.
    auto* matrices = static_cast<DrawConstants*>(frame.matrices.buffer.mapped);
    for (size_t d = 0; d < draws; ++d) {
        const common::Draw& draw = scene.draws[d];
        matrices[d] = {draw.model,
                       {glm::vec4(draw.normalMatrix[0], 0.0f), glm::vec4(draw.normalMatrix[1], 0.0f),
                        glm::vec4(draw.normalMatrix[2], 0.0f)}};
    }
    std::vector<std::pair<uint32_t, uint32_t>> order;
    order.reserve(draws);
    for (uint32_t d : buffers.sceneOrder) order.push_back({d, 0u});
    appendCommands(scene, order, static_cast<InstanceData*>(frame.instances.buffer.mapped),
                   frame.instanceCount, static_cast<VkDrawIndirectCommand*>(frame.commands.buffer.mapped),
                   frame.commandCount, buffers.sceneGroups);
    buffers.sceneCommands = frame.commandCount;
    buffers.sceneInstances = frame.instanceCount;
}
//< update-buffers

//> record-scene
void recordIndirectScene(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                         const ScenePass& scenePass) {
    const FrameBuffers& frame = buffers.frames[slot];
    if (buffers.sceneGroups.empty()) return;
    const ScenePipelines& pipelines = scenePass.pipelines;
    pushAddresses(cmd, pipelines.layout, frame);
    VkPipeline bound = VK_NULL_HANDLE;
    buffers.sceneIndirectDraws = 0;
    drawGroups(
        cmd, buffers, frame, buffers.sceneGroups, pipelines.layout, scenePass,
        [&](const IndirectGroup& group) {
            return pipelines.pipelines[pipelines.materialClasses.ofMaterial[group.material]];
        },
        bound, buffers.sceneIndirectDraws);
}
//< record-scene

//> record-shadow
void recordIndirectShadowBatch(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                               const ShadowPass& shadowPass, const ScenePass& scenePass,
                               const common::GpuScene& scene, const std::vector<ShadowDraw>& draws,
                               VkPipeline& bound) {
    if (draws.empty()) return;
    FrameBuffers& frame = buffers.frames[slot];
    // The batch's draws by (opaque before cut-out, material, mesh): a command per mesh, its instances
    // each with the cascades the plan sends it to.
    std::vector<std::pair<uint32_t, uint32_t>> order;
    order.reserve(draws.size());
    for (const ShadowDraw& draw : draws) order.push_back({draw.draw, draw.layers});
    std::sort(order.begin(), order.end(), [&](const auto& a, const auto& b) {
        const common::Draw& x = scene.draws[a.first];
        const common::Draw& y = scene.draws[b.first];
        return std::tuple(scene.materials[x.material].alphaTested, x.material, x.mesh, a.first) <
               std::tuple(scene.materials[y.material].alphaTested, y.material, y.mesh, b.first);
    });
    const uint32_t firstCommand = frame.commandCount, firstInstance = frame.instanceCount;
    std::vector<IndirectGroup> groups;
    appendCommands(scene, order, static_cast<InstanceData*>(frame.instances.buffer.mapped),
                   frame.instanceCount, static_cast<VkDrawIndirectCommand*>(frame.commands.buffer.mapped),
                   frame.commandCount, groups);
    buffers.shadowCommands += frame.commandCount - firstCommand;
    buffers.shadowInstances += frame.instanceCount - firstInstance;
    pushAddresses(cmd, shadowPass.pipelineLayout, frame);
    drawGroups(
        cmd, buffers, frame, groups, shadowPass.pipelineLayout, scenePass,
        [&](const IndirectGroup& group) { return group.alphaTested ? shadowPass.cutout : shadowPass.opaque; },
        bound, buffers.shadowIndirectDraws);
}
//< record-shadow

std::string describeGlobalBuffers(const GlobalBuffers& b) {
    return "scene " + std::to_string(b.sceneCommands) + " commands for " + std::to_string(b.sceneInstances) +
           " instances in " + std::to_string(b.sceneIndirectDraws) + " indirect draws; shadow " +
           std::to_string(b.shadowCommands) + " commands for " + std::to_string(b.shadowInstances) +
           " instances in " + std::to_string(b.shadowIndirectDraws) + " indirect draws; " +
           std::to_string(b.grown) + " buffers made";
}

void destroyGlobalBuffers(const common::Device& device, GlobalBuffers& buffers) {
    for (FrameBuffers& frame : buffers.frames)
        for (GrowingBuffer* growing : {&frame.matrices, &frame.instances, &frame.commands})
            if (growing->buffer.handle != VK_NULL_HANDLE) common::destroyBuffer(device, growing->buffer);
    buffers = {};
}
