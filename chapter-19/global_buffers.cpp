// chapter-19: the book's GlobalBuffers (global_buffers.hpp).
#include "global_buffers.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include "chapter-15/gpu_types.hpp"
#include "common/core/check.hpp"
#include "common/vk/commands.hpp"

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

// One indirect draw per group (more past maxDrawIndirectCount), its pipeline (when it changes), its
// material's textures and index bound first.
template <typename PipelineOf>
void drawGroups(VkCommandBuffer cmd, const GlobalBuffers& buffers, const FrameBuffers& frame,
                const std::vector<IndirectGroup>& groups, VkPipelineLayout layout, const ScenePass& scenePass,
                PipelineOf pipelineOf, VkPipeline& bound, uint32_t& calls) {
    for (const IndirectGroup& group : groups) {
        VkPipeline pipeline = pipelineOf(group);
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1,
                                &scenePass.materialTextureSets[group.material], 0, nullptr);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, kIndirectMaterialOffset,
                           sizeof(uint32_t), &group.material);
        for (uint32_t first = 0; first < group.commandCount; first += buffers.maxDrawIndirectCount) {
            uint32_t count = std::min(buffers.maxDrawIndirectCount, group.commandCount - first);
            vkCmdDrawIndexedIndirect(
                cmd, frame.commands.buffer.handle,
                VkDeviceSize(group.firstCommand + first) * sizeof(VkDrawIndexedIndirectCommand), count,
                sizeof(VkDrawIndexedIndirectCommand));
            ++calls;
        }
    }
}

// What every draw of a pass reads: the frame's instances and matrices (their addresses), and the
// scene's index buffer.
void bindFrame(VkCommandBuffer cmd, VkPipelineLayout layout, const GlobalBuffers& buffers,
               const FrameBuffers& frame) {
    IndirectConstants constants{frame.instances.buffer.address, frame.matrices.buffer.address};
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(constants), &constants);
    vkCmdBindIndexBuffer(cmd, buffers.indices.buffer.handle, 0, VK_INDEX_TYPE_UINT32);
}

void append(FrameBuffers& frame, const common::GpuScene& scene, const std::vector<uint32_t>& firstIndex,
            const std::vector<std::pair<uint32_t, uint32_t>>& draws, std::vector<IndirectGroup>& groups) {
    appendCommands(scene, firstIndex, draws, static_cast<InstanceData*>(frame.instances.buffer.mapped),
                   frame.instanceCount,
                   static_cast<VkDrawIndexedIndirectCommand*>(frame.commands.buffer.mapped),
                   frame.commandCount, groups);
}

}  // namespace

//> scene-indices
SceneIndices createSceneIndices(const common::Device& device, const common::GpuScene& scene) {
    SceneIndices indices;
    // Each distinct index buffer once (a posed mesh draws its source's; a mirrored copy has its own).
    std::map<VkBuffer, uint32_t> placed;
    std::vector<std::pair<const common::GpuMesh*, uint32_t>> copies;
    for (const common::GpuMesh& mesh : scene.meshes) {
        auto [at, fresh] = placed.emplace(mesh.indices.handle, uint32_t(indices.count));
        if (fresh) {
            copies.push_back({&mesh, uint32_t(indices.count)});
            indices.count += mesh.indexCount;
            if (indices.count > UINT32_MAX)
                throw common::Failure("the scene's meshes have more than 2^32 indices in all");
        }
        indices.firstIndex.push_back(at->second);
    }
    if (indices.count == 0) return indices;  // no mesh: no buffer
    indices.buffer = common::createBuffer(device, indices.count * sizeof(uint32_t),
                                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "scene indices");
    // Copied on the GPU from the meshes' own index buffers, once; waited for before the first frame.
    VkCommandBuffer cmd = common::beginOneTimeCommands(device);
    for (const auto& [mesh, first] : copies) {
        VkBufferCopy region{0, VkDeviceSize(first) * sizeof(uint32_t),
                            VkDeviceSize(mesh->indexCount) * sizeof(uint32_t)};
        if (region.size > 0) vkCmdCopyBuffer(cmd, mesh->indices.handle, indices.buffer.handle, 1, &region);
    }
    common::submitOneTimeCommands(device, cmd);
    return indices;
}
//< scene-indices

void destroySceneIndices(const common::Device& device, SceneIndices& indices) {
    if (indices.buffer.handle != VK_NULL_HANDLE) common::destroyBuffer(device, indices.buffer);
    indices = {};
}

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
void appendCommands(const common::GpuScene& scene, const std::vector<uint32_t>& firstIndex,
                    const std::vector<std::pair<uint32_t, uint32_t>>& draws, InstanceData* instances,
                    uint32_t& instanceCount, VkDrawIndexedIndirectCommand* commands, uint32_t& commandCount,
                    std::vector<IndirectGroup>& groups) {
    uint32_t lastMesh = UINT32_MAX, lastMaterial = UINT32_MAX;
    for (const auto& [drawIndex, layers] : draws) {
        const common::Draw& draw = scene.draws[drawIndex];
        const common::GpuMesh& mesh = scene.meshes[draw.mesh];
        if (draw.material != lastMaterial) {
            groups.push_back({draw.material, scene.materials[draw.material].alphaTested, commandCount, 0});
            lastMesh = UINT32_MAX;
        }
        if (draw.mesh != lastMesh) {
            // The mesh's indices where the scene's index buffer holds them; the index values are the
            // mesh's own (vertexOffset 0), the vertices pulled from the instance's vertex buffer.
            commands[commandCount++] = {mesh.indexCount, 0, firstIndex[draw.mesh], 0, instanceCount};
            ++groups.back().commandCount;
        }
        ++commands[commandCount - 1].instanceCount;
        instances[instanceCount++] = {drawIndex, layers, mesh.vertices.address};
        lastMesh = draw.mesh;
        lastMaterial = draw.material;
    }
}
//< append-commands

GlobalBuffers createGlobalBuffers(const common::Device& device, const common::GpuScene& scene,
                                  uint32_t framesInFlight) {
    GlobalBuffers buffers;
    buffers.indices = createSceneIndices(device, scene);
    buffers.frames.resize(framesInFlight);
    // A device with multiDrawIndirect draws at least 65,535 commands a call.
    buffers.maxDrawIndirectCount = std::max(1u, device.properties.limits.maxDrawIndirectCount);
    return buffers;
}

//> update-buffers
void updateGlobalBuffers(const common::Device& device, GlobalBuffers& buffers, uint32_t slot,
                         const common::GpuScene& scene, const ScenePass& scenePass, const ShadowPlan& plan) {
    FrameBuffers& frame = buffers.frames[slot];
    const size_t draws = scene.draws.size();
    // The order the scene pass draws in (sceneDrawOrder), made once: draws keep their mesh and
    // material (only their matrices move).
    if (buffers.sceneOrder.size() != draws)
        buffers.sceneOrder = sceneDrawOrder(scene, scenePass.pipelines.materialClasses.ofMaterial);
    // Room for the scene's instances and commands and the shadow plan's; matrices for every draw.
    uint64_t shadowDraws = 0;
    for (const std::vector<ShadowBatch>* batches : {&plan.cached, &plan.moving})
        for (const ShadowBatch& batch : *batches) shadowDraws += batch.draws.size();
    const uint64_t instances = draws + shadowDraws;
    if (instances > UINT32_MAX) throw common::Failure("more instances in a frame than 2^32");
    std::string name = "frame " + std::to_string(slot) + " ";
    reserve(device, frame.matrices, draws * sizeof(DrawConstants), kAddressed, name + "matrices",
            buffers.grown);
    reserve(device, frame.instances, instances * sizeof(InstanceData), kAddressed, name + "instances",
            buffers.grown);
    reserve(device, frame.commands, instances * sizeof(VkDrawIndexedIndirectCommand),
            VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, name + "draw commands", buffers.grown);
    frame.instanceCount = frame.commandCount = 0;
    frame.sceneGroups.clear();
    frame.shadowBatches.clear();
    frame.sceneCommands = frame.sceneInstances = frame.shadowCommands = frame.shadowInstances = 0;
    frame.sceneIndirectDraws = frame.shadowIndirectDraws = 0;
    buffers.lastSlot = slot;
    if (draws == 0) return;  // nothing to draw: nothing made, nothing written
    if (buffers.indices.firstIndex.size() != scene.meshes.size())
        throw common::Failure("chapter-19: the scene has meshes its index buffer was not made with");

    // Every draw's matrices, where this frame has put them.
    auto* matrices = static_cast<DrawConstants*>(frame.matrices.buffer.mapped);
    for (size_t d = 0; d < draws; ++d) {
        const common::Draw& draw = scene.draws[d];
        matrices[d] = {draw.model,
                       {glm::vec4(draw.normalMatrix[0], 0.0f), glm::vec4(draw.normalMatrix[1], 0.0f),
                        glm::vec4(draw.normalMatrix[2], 0.0f)}};
    }
    // The scene pass: every draw, a command per mesh and material.
    std::vector<std::pair<uint32_t, uint32_t>> order;
    order.reserve(draws);
    for (uint32_t d : buffers.sceneOrder) order.push_back({d, 0u});
    append(frame, scene, buffers.indices.firstIndex, order, frame.sceneGroups);
    frame.sceneCommands = frame.commandCount;
    frame.sceneInstances = frame.instanceCount;
    // The shadow pass: each batch of the plan's, its draws by (opaque before cut-out, material,
    // mesh), each instance with the cascades the plan sends it to.
    for (const std::vector<ShadowBatch>* batches : {&plan.cached, &plan.moving})
        for (const ShadowBatch& batch : *batches) {
            if (batch.draws.empty()) continue;
            order.clear();
            for (const ShadowDraw& draw : batch.draws) order.push_back({draw.draw, draw.layers});
            std::sort(order.begin(), order.end(), [&](const auto& a, const auto& b) {
                const common::Draw& x = scene.draws[a.first];
                const common::Draw& y = scene.draws[b.first];
                return std::tuple(scene.materials[x.material].alphaTested, x.material, x.mesh, a.first) <
                       std::tuple(scene.materials[y.material].alphaTested, y.material, y.mesh, b.first);
            });
            frame.shadowBatches.push_back({&batch.draws, {}});
            append(frame, scene, buffers.indices.firstIndex, order, frame.shadowBatches.back().groups);
        }
    frame.shadowCommands = frame.commandCount - frame.sceneCommands;
    frame.shadowInstances = frame.instanceCount - frame.sceneInstances;
}
//< update-buffers

//> record-scene
void recordIndirectScene(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                         const ScenePass& scenePass) {
    FrameBuffers& frame = buffers.frames[slot];
    if (frame.sceneGroups.empty()) return;
    const ScenePipelines& pipelines = scenePass.pipelines;
    bindFrame(cmd, pipelines.layout, buffers, frame);
    VkPipeline bound = VK_NULL_HANDLE;
    drawGroups(
        cmd, buffers, frame, frame.sceneGroups, pipelines.layout, scenePass,
        [&](const IndirectGroup& group) {
            return pipelines.pipelines[pipelines.materialClasses.ofMaterial[group.material]];
        },
        bound, frame.sceneIndirectDraws);
}
//< record-scene

//> record-shadow
void recordIndirectShadowBatch(VkCommandBuffer cmd, GlobalBuffers& buffers, uint32_t slot,
                               const ShadowPass& shadowPass, const ScenePass& scenePass,
                               const std::vector<ShadowDraw>& draws, VkPipeline& bound) {
    FrameBuffers& frame = buffers.frames[slot];
    auto batch = std::find_if(frame.shadowBatches.begin(), frame.shadowBatches.end(),
                              [&](const FrameBuffers::ShadowBatchGroups& b) { return b.draws == &draws; });
    if (batch == frame.shadowBatches.end())
        throw common::Failure(
            "chapter-19: a shadow batch was recorded that the frame's update did not write");
    bindFrame(cmd, shadowPass.pipelineLayout, buffers, frame);
    drawGroups(
        cmd, buffers, frame, batch->groups, shadowPass.pipelineLayout, scenePass,
        [&](const IndirectGroup& group) { return group.alphaTested ? shadowPass.cutout : shadowPass.opaque; },
        bound, frame.shadowIndirectDraws);
}
//< record-shadow

std::string describeGlobalBuffers(const GlobalBuffers& buffers) {
    if (buffers.frames.empty()) return "nothing drawn";
    const FrameBuffers& b = buffers.frames[buffers.lastSlot];
    return "scene " + std::to_string(b.sceneCommands) + " commands for " + std::to_string(b.sceneInstances) +
           " instances in " + std::to_string(b.sceneIndirectDraws) + " indirect draws; shadow " +
           std::to_string(b.shadowCommands) + " commands for " + std::to_string(b.shadowInstances) +
           " instances in " + std::to_string(b.shadowIndirectDraws) + " indirect draws; " +
           std::to_string(buffers.grown) + " buffers made";
}

void destroyGlobalBuffers(const common::Device& device, GlobalBuffers& buffers) {
    for (FrameBuffers& frame : buffers.frames)
        for (GrowingBuffer* growing : {&frame.matrices, &frame.instances, &frame.commands})
            if (growing->buffer.handle != VK_NULL_HANDLE) common::destroyBuffer(device, growing->buffer);
    destroySceneIndices(device, buffers.indices);
    buffers = {};
}
