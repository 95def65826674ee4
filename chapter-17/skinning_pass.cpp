// chapter-17: the skinning pass (skinning_pass.hpp). The book's first compute pipeline: every call
// it takes is written out here -- the compute pipeline, its dispatch, the barriers that order it
// against the frames' vertex reads.
#include "skinning_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <string>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"

namespace {

// What skin.comp reads per vertex beside its bind-pose vertex (scalar layout, 24 bytes).
struct GpuInfluence {
    uint32_t joints[2];  // joints 0 and 1, 2 and 3: 16 bits each, the first in the low half
    glm::vec4 weights;
};
static_assert(sizeof(GpuInfluence) == 24, "skin.comp reads Influence with this layout");

struct DispatchConstants {
    uint32_t count;
    uint32_t paletteBase;
};

// What a scene may ask of the pass: the palette is uploaded each frame (128 bytes a joint), the
// posed vertices take device memory beside the bind pose.
constexpr uint64_t kMaxPaletteJoints = uint64_t{1} << 17;  // 16 MiB a frame
constexpr uint64_t kMaxSkinnedBytes = uint64_t{1} << 30;

//> compute-pipeline
// The pipeline from the shader's current code: at start-up, and again on a live reload. A
// compute pipeline is one shader stage and its layout: no vertex input, no rasterisation.
VkPipeline makeSkinningPipeline(const common::Device& device, VkPipelineCache cache,
                                const SkinningPass& pass) {
    common::ShaderModule module(device, pass.shader);
    VkComputePipelineCreateInfo pipelineInfo{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module),
        .layout = pass.pipelineLayout,
    };
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device.handle, cache, 1, &pipelineInfo, nullptr, &pipeline));
    common::nameObject(device.handle, pipeline, pass.shader);
    return pipeline;
}
//< compute-pipeline

// A vertex buffer for one instance's posed mesh: the shader writes it, the passes read it as
// vertices, --check-skinning copies it out. Filled with 0xFF bytes, guard included, in the
// staging batch's submission.
common::Buffer createPosedBuffer(const common::Device& device, common::StagingBatch& batch, uint32_t vertices,
                                 VkBufferUsageFlags addressed, const std::string& name) {
    VkDeviceSize size = VkDeviceSize(vertices + kGuardVertices) * sizeof(common::Vertex);
    common::Buffer buffer = common::createBuffer(
        device, size,
        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
            VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | addressed,
        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    vkCmdFillBuffer(batch.commandBuffer, buffer.handle, 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);  // with the uploads
    return buffer;
}

// chapter-18's end of createSkinningPass: no descriptor sets; each chunk's addresses, per frame in
// flight, pushed with its dispatch. A pointer reaches the whole buffer, so only the dispatch's group
// limit cuts a mesh into chunks.
SkinningPass createAddressedSkinning(const common::Device& device, VkPipelineCache cache, SkinningPass pass,
                                     const common::GpuScene& scene, uint32_t framesInFlight) {
    for (uint32_t slot = 0; slot < framesInFlight; ++slot)
        pass.palettes.push_back(common::createBuffer(
            device, VkDeviceSize(pass.paletteJoints) * sizeof(common::PaletteEntry),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
            "joint palette " + std::to_string(slot)));
    const uint64_t chunkVertices = uint64_t(pass.maxGroups) * 32;
    for (SkinnedModel& model : pass.models)
        for (SkinnedMesh& mesh : model.meshes)
            for (uint64_t first = 0; first < mesh.vertexCount; first += chunkVertices) {
                SkinnedMesh::Chunk chunk{
                    uint32_t(first),
                    uint32_t(std::min<uint64_t>(chunkVertices, mesh.vertexCount - first)),
                    {},
                    {}};
                for (uint32_t slot = 0; slot < framesInFlight; ++slot)
                    chunk.addresses.push_back(
                        {.bindPose =
                             scene.meshes[mesh.sourceMesh].vertices.address + first * sizeof(common::Vertex),
                         .influences = mesh.influences.address + first * sizeof(GpuInfluence),
                         .palette = pass.palettes[slot].address +
                                    uint64_t(model.paletteBase) * sizeof(common::PaletteEntry),
                         .skinned =
                             scene.meshes[mesh.outputMesh].vertices.address + first * sizeof(common::Vertex),
                         .count = chunk.count});
                mesh.chunks.push_back(std::move(chunk));
            }
    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(SkinningAddresses)};
    pass.pipelineLayout = common::createPipelineLayout(device, {}, {&push, 1}, "skinning");
    pass.pipeline = makeSkinningPipeline(device, cache, pass);
    return pass;
}

}  // namespace

//> create-skinning
SkinningPass createSkinningPass(const common::Device& device, VkPipelineCache cache, common::GpuScene& scene,
                                const common::Scene& sceneDesc, common::ModelCache& models,
                                uint32_t framesInFlight, const SkinningOptions& options) {
    SkinningPass pass;
    pass.shader = options.shader;
    pass.deviceAddresses = options.deviceAddresses;
    // chapter-18: every buffer the shader reads or writes is found by its address.
    const VkBufferUsageFlags addressed =
        options.deviceAddresses ? VkBufferUsageFlags(VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) : 0u;
    pass.maxGroups = device.properties.limits.maxComputeWorkGroupCount[0];
    pass.dispatch.assign(framesInFlight, 0);
    // Each instance's draws, in the order loadGpuScene made them: its model's meshes, then its repeats.
    std::vector<std::vector<uint32_t>> drawsOf(sceneDesc.models.size());
    for (uint32_t d = 0; d < scene.draws.size(); ++d) drawsOf[scene.draws[d].instance].push_back(d);
    // The allocations the pass will make, counted before any is (as loadGpuScene counts the
    // scene's): a posed buffer per instance and skinned mesh, the influences (and their staging
    // copies) per distinct mesh, a palette per frame in flight.
    {
        uint64_t posed = 0;
        std::set<const common::MeshData*> distinct;
        for (uint32_t instance = 0; instance < sceneDesc.models.size(); ++instance) {
            const common::ModelData& model = common::loadModelCached(models, sceneDesc.models[instance].file);
            if (model.rig.empty()) continue;
            std::set<uint32_t> meshes;
            const std::vector<uint32_t>& draws = drawsOf[instance];
            for (size_t k = 0; k < draws.size(); ++k) {
                const size_t m = k < model.meshes.size() ? k : model.repeats[k - model.meshes.size()].mesh;
                if (model.meshes[m].skin.empty()) continue;
                meshes.insert(scene.draws[draws[k]].mesh);
                distinct.insert(&model.meshes[m]);
            }
            posed += meshes.size();
        }
        const uint64_t existing = 2 * scene.meshes.size() + scene.textures.size(), renderer = 64;
        const uint64_t needed = posed + 2 * distinct.size() + framesInFlight;
        const uint64_t limit = device.properties.limits.maxMemoryAllocationCount;
        if (existing + needed + renderer > limit)
            throw common::InputError(
                "the scene's animated models need " + std::to_string(needed) +
                " more memory allocations (a buffer per instance and skinned mesh) beside the "
                "scene's " +
                std::to_string(existing) + "; this device allows " + std::to_string(limit) +
                ", of which the renderer keeps " + std::to_string(renderer));
    }
    uint64_t skinnedBytes = 0;
    common::StagingBatch batch = common::beginStaging(device);
    std::map<const common::MeshData*, size_t> influenceOwner;  // the first SkinnedMesh that uploaded them
    std::vector<std::pair<size_t, size_t>> ownerPlace;         // (model, mesh) of each owner
    for (uint32_t instance = 0; instance < sceneDesc.models.size(); ++instance) {
        const common::ModelData& model = common::loadModelCached(models, sceneDesc.models[instance].file);
        if (model.rig.empty()) continue;
        SkinnedModel skinned{.instance = instance,
                             .name = common::utf8(sceneDesc.models[instance].file),
                             .model = &model,
                             .paletteBase = pass.paletteJoints};
        std::map<uint32_t, size_t> outputOf;  // GpuScene mesh -> its SkinnedMesh here
        const std::vector<uint32_t>& draws = drawsOf[instance];
        for (size_t k = 0; k < draws.size(); ++k) {
            const size_t meshIndex =
                k < model.meshes.size() ? k : model.repeats[k - model.meshes.size()].mesh;
            const common::MeshData& data = model.meshes[meshIndex];
            if (data.skin.empty()) continue;
            common::Draw& draw = scene.draws[draws[k]];
            auto found = outputOf.find(draw.mesh);
            if (found == outputOf.end()) {
                SkinnedMesh mesh{
                    .sourceMesh = draw.mesh, .data = &data, .vertexCount = uint32_t(data.vertices.size())};
                skinnedBytes += uint64_t(mesh.vertexCount + kGuardVertices) * sizeof(common::Vertex);
                if (skinnedBytes > kMaxSkinnedBytes)
                    throw common::InputError(common::utf8(sceneDesc.models[instance].file) +
                                             ": the scene's animated models need more than " +
                                             std::to_string(kMaxSkinnedBytes >> 20) +
                                             " MiB of posed vertices (a buffer per instance and mesh)");
                // The posed copy draws the source's indices (mirrored ones too) with vertices of its own.
                common::GpuMesh posed = scene.meshes[draw.mesh];
                posed.ownsIndices = false;
                posed.ownsVertices = true;
                posed.vertices = createPosedBuffer(device, batch, mesh.vertexCount, addressed,
                                                   "posed vertices: model " + std::to_string(instance) +
                                                       ", mesh " + std::to_string(meshIndex));
                mesh.outputMesh = uint32_t(scene.meshes.size());
                scene.meshes.push_back(posed);
                mesh.bounds = common::skinBounds(data);
                found = outputOf.emplace(draw.mesh, skinned.meshes.size()).first;
                skinned.meshes.push_back(std::move(mesh));
            }
            draw.mesh = skinned.meshes[found->second].outputMesh;
        }
        if (skinned.meshes.empty()) continue;
        pass.paletteJoints += uint32_t(model.rig.joints.size());
        if (pass.paletteJoints > kMaxPaletteJoints)
            throw common::InputError(common::utf8(sceneDesc.models[instance].file) +
                                     ": the scene's animated models have more than " +
                                     std::to_string(kMaxPaletteJoints) + " joints in all");
        // Each mesh's influences, uploaded once however many instances pose it.
        for (SkinnedMesh& mesh : skinned.meshes) {
            auto owner = influenceOwner.find(mesh.data);
            if (owner != influenceOwner.end()) {
                auto [m, s] = ownerPlace[owner->second];
                mesh.influences = (m == pass.models.size() ? skinned : pass.models[m]).meshes[s].influences;
                mesh.ownsInfluences = false;
                continue;
            }
            std::vector<GpuInfluence> influences(mesh.data->skin.size());
            for (size_t v = 0; v < influences.size(); ++v) {
                const common::VertexSkin& s = mesh.data->skin[v];
                influences[v] = {{uint32_t(s.joints[0]) | uint32_t(s.joints[1]) << 16,
                                  uint32_t(s.joints[2]) | uint32_t(s.joints[3]) << 16},
                                 s.weights};
            }
            mesh.influences = common::uploadStaged(
                device, batch, influences.data(), influences.size() * sizeof(GpuInfluence),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | addressed, "skin influences");
            influenceOwner[mesh.data] = ownerPlace.size();
            ownerPlace.push_back({pass.models.size(), size_t(&mesh - skinned.meshes.data())});
        }
        // The scene's bounds: where the clips may take the model (the loader's animated bounds).
        glm::mat4 matrix = sceneDesc.models[instance].transform.matrix();
        for (int c = 0; c < 8; ++c) {
            glm::vec3 p =
                glm::vec3(matrix * glm::vec4(common::boxCorner(c, model.boundsMin, model.boundsMax), 1.0f));
            scene.boundsMin = glm::min(scene.boundsMin, p);
            scene.boundsMax = glm::max(scene.boundsMax, p);
        }
        pass.models.push_back(std::move(skinned));
    }
    common::endStaging(device, batch);
    if (pass.models.empty()) return pass;  // nothing animated: no pass at all
    if (pass.deviceAddresses)
        return createAddressedSkinning(device, cache, std::move(pass), scene, framesInFlight);

    // Set 0: the bind pose, the influences, the palette, the posed vertices -- all storage buffers.
    pass.setLayout = common::createDescriptorSetLayout(
        device,
        {common::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT),
         common::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT),
         common::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT),
         common::binding(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT)},
        "skinning");
    // Each mesh in chunks: a storage buffer's binding may span at most maxStorageBufferRange bytes
    // (128 MiB on many devices: 2.4 million vertices), a dispatch at most
    // maxComputeWorkGroupCount[0] groups; a chunk is a whole number of groups of 32, so that its
    // offsets in the vertex (56 bytes) and influence (24 bytes) buffers are multiples of 256, the
    // largest minStorageBufferOffsetAlignment a device may have.
    const VkPhysicalDeviceLimits& limits = device.properties.limits;
    const uint64_t bindable =
        limits.maxStorageBufferRange / sizeof(common::Vertex);  // the last chunk's guard too
    const uint64_t chunkVertices =
        std::min<uint64_t>(bindable > kGuardVertices ? bindable - kGuardVertices : 0,
                           uint64_t(pass.maxGroups) * 32) /
        32 * 32;
    if (chunkVertices == 0) throw common::Failure("this device's storage buffers are too small to skin with");
    uint32_t chunks = 0;
    for (SkinnedModel& model : pass.models)
        for (SkinnedMesh& mesh : model.meshes)
            for (uint64_t first = 0; first < mesh.vertexCount; first += chunkVertices) {
                mesh.chunks.push_back({uint32_t(first),
                                       uint32_t(std::min<uint64_t>(chunkVertices, mesh.vertexCount - first)),
                                       {}});
                ++chunks;
            }
    pass.descriptorPool = common::createDescriptorPool(
        device, chunks * framesInFlight, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4 * chunks * framesInFlight}},
        "skinning");
    for (uint32_t slot = 0; slot < framesInFlight; ++slot)
        pass.palettes.push_back(
            common::createBuffer(device, VkDeviceSize(pass.paletteJoints) * sizeof(common::PaletteEntry),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                 "joint palette " + std::to_string(slot)));
    // A chunk's sets: its range of the bind pose, the influences and the posed vertices (the last
    // chunk's with the guard: a write past the mesh would land there), and the frame's palette.
    auto write = [&](VkDescriptorSet set, uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                     VkDeviceSize range) {
        VkDescriptorBufferInfo info{buffer, offset, range};
        VkWriteDescriptorSet update{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                    .dstSet = set,
                                    .dstBinding = binding,
                                    .descriptorCount = 1,
                                    .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                    .pBufferInfo = &info};
        vkUpdateDescriptorSets(device.handle, 1, &update, 0, nullptr);
    };
    for (SkinnedModel& model : pass.models)
        for (SkinnedMesh& mesh : model.meshes)
            for (SkinnedMesh::Chunk& chunk : mesh.chunks) {
                const bool last = chunk.first + chunk.count == mesh.vertexCount;
                const VkDeviceSize vertexBytes = sizeof(common::Vertex),
                                   influenceBytes = sizeof(GpuInfluence);
                for (uint32_t slot = 0; slot < framesInFlight; ++slot) {
                    VkDescriptorSet set = common::allocateDescriptorSet(device, pass.descriptorPool,
                                                                        pass.setLayout, "skinning");
                    write(set, 0, scene.meshes[mesh.sourceMesh].vertices.handle, chunk.first * vertexBytes,
                          chunk.count * vertexBytes);
                    write(set, 1, mesh.influences.handle, chunk.first * influenceBytes,
                          chunk.count * influenceBytes);
                    write(set, 2, pass.palettes[slot].handle, 0, VK_WHOLE_SIZE);
                    write(set, 3, scene.meshes[mesh.outputMesh].vertices.handle, chunk.first * vertexBytes,
                          (chunk.count + (last ? kGuardVertices : 0)) * vertexBytes);
                    chunk.sets.push_back(set);
                }
            }
    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(DispatchConstants)};
    pass.pipelineLayout = common::createPipelineLayout(device, {&pass.setLayout, 1}, {&push, 1}, "skinning");
    pass.pipeline = makeSkinningPipeline(device, cache, pass);
    return pass;
}
//< create-skinning

//> pose
void poseSkinnedModels(SkinningPass& pass, common::GpuScene& scene, const AnimationClock& clock,
                       uint32_t slot) {
    pass.dispatch.at(slot) = 0;
    if (pass.models.empty()) return;
    const bool changed = pass.stale || clock.seconds != pass.posedAt || clock.clip != pass.posedClip;
    for (SkinnedModel& model : pass.models)
        for (const SkinnedMesh& mesh : model.meshes) scene.meshes[mesh.outputMesh].deforms = changed;
    if (!changed) return;  // the buffers hold this pose already: no dispatch, no upload
    auto* palette = static_cast<common::PaletteEntry*>(pass.palettes[slot].mapped);
    for (SkinnedModel& model : pass.models) {
        const common::Rig& rig = model.model->rig;
        const int clip = rig.clips.empty() ? -1 : std::min(clock.clip, int(rig.clips.size()) - 1);
        common::poseRig(rig, clip, clock.seconds, model.pose);
        // A pose no float holds (a clip's key between the load's samples may reach it): stopped
        // in one line rather than drawn as NaN.
        auto refuse = [&](const char* what) {
            throw common::InputError(model.name + ": its pose at " + std::to_string(clock.seconds) + " s " +
                                     what);
        };
        for (size_t j = 0; j < model.pose.joints.size(); ++j) {
            common::PaletteEntry entry = common::paletteEntry(model.pose.joints[j]);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    if (!std::isfinite(entry.joint[c][r]) || !std::isfinite(entry.normal[c][r]))
                        refuse("has a joint matrix that is not finite in 32-bit floats");
            palette[model.paletteBase + j] = entry;
        }
        for (const SkinnedMesh& mesh : model.meshes) {
            common::GpuMesh& posed = scene.meshes[mesh.outputMesh];
            common::posedBounds(mesh.bounds, model.pose.joints, posed.boundsMin, posed.boundsMax);
            for (int a = 0; a < 3; ++a)
                if (!(std::abs(posed.boundsMin[a]) <= common::kMaxModelCoordinate) ||
                    !(std::abs(posed.boundsMax[a]) <= common::kMaxModelCoordinate))
                    refuse("reaches beyond 1e15 from the origin (or a number that is not finite)");
        }
    }
    pass.dispatch[slot] = 1;
    pass.stale = false;
    pass.posedAt = clock.seconds;
    pass.posedClip = clock.clip;
}
//< pose

//> record-skinning
void recordSkinningPass(VkCommandBuffer cmd, SkinningPass& pass, uint32_t slot) {
    if (!pass.dispatch.at(slot)) return;
    // The posed buffers are read as vertices by the frames before this one (same queue): their
    // reads end before the shader writes, and the last frame's writes (and the fill that made
    // the buffers) are ordered before these.
    // Read by the vertex input (chapter-17), or by the vertex shaders that pull them (chapter-18).
    const VkPipelineStageFlags2 vertexReads = pass.deviceAddresses
                                                  ? VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT
                                                  : VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT;
    VkMemoryBarrier2 beforeWrites{
        .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
        .srcStageMask =
            vertexReads | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
        .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
        .dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    VkDependencyInfo before{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                            .memoryBarrierCount = 1,
                            .pMemoryBarriers = &beforeWrites};
    common::vk13.CmdPipelineBarrier2(cmd, &before);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline);
    uint64_t vertices = 0;
    uint32_t dispatches = 0;
    for (const SkinnedModel& model : pass.models)
        for (const SkinnedMesh& mesh : model.meshes) {
            // A dispatch a chunk: ceil(count / 32) groups; the shader returns for the last group's
            // invocations past the chunk.
            for (const SkinnedMesh::Chunk& chunk : mesh.chunks) {
                if (pass.deviceAddresses) {  // chapter-18: the chunk's buffers by their addresses
                    vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                                       sizeof(SkinningAddresses), &chunk.addresses[slot]);
                    vkCmdDispatch(cmd, (chunk.count + 31) / 32, 1, 1);
                    ++dispatches;
                    continue;
                }
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipelineLayout, 0, 1,
                                        &chunk.sets[slot], 0, nullptr);
                DispatchConstants constants{chunk.count, model.paletteBase};
                vkCmdPushConstants(cmd, pass.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                                   sizeof(constants), &constants);
                vkCmdDispatch(cmd, (chunk.count + 31) / 32, 1, 1);
                ++dispatches;
            }
            vertices += mesh.vertexCount;
        }

    // The posed vertices written before any pass of this frame fetches them.
    VkMemoryBarrier2 afterWrites{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                 .srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                 .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                 .dstStageMask = vertexReads,
                                 .dstAccessMask = pass.deviceAddresses
                                                      ? VK_ACCESS_2_SHADER_STORAGE_READ_BIT
                                                      : VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT};
    VkDependencyInfo after{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1, .pMemoryBarriers = &afterWrites};
    common::vk13.CmdPipelineBarrier2(cmd, &after);
    ++pass.dispatchedFrames;
    pass.vertices = vertices;
    pass.dispatches = dispatches;
}
//< record-skinning

void remakeSkinningPipeline(const common::Device& device, VkPipelineCache cache, SkinningPass& pass,
                            const common::ShaderReload& reload, common::PipelineSwap& swap) {
    if (pass.pipeline == VK_NULL_HANDLE || !reload.changed({pass.shader})) return;
    common::replacePipeline(swap, pass.pipeline, [&] { return makeSkinningPipeline(device, cache, pass); });
    pass.stale = true;  // skinned again with the new shader, even when paused
}

void checkSkinning(const char* chapter, const common::Device& device, const SkinningPass& pass,
                   const common::GpuScene& scene) {
    if (pass.models.empty()) {
        std::printf("%s: skinning check: nothing is skinned\n", chapter);
        return;
    }
    double maxPosition = 0.0, maxNormal = 0.0;
    std::vector<double> positionErrors;
    uint64_t checked = 0, meshes = 0;
    for (const SkinnedModel& model : pass.models) {
        common::Pose pose;
        const common::Rig& rig = model.model->rig;
        const int clip = rig.clips.empty() ? -1 : std::min(pass.posedClip, int(rig.clips.size()) - 1);
        common::poseRig(rig, clip, pass.posedAt, pose);
        const double size =
            std::max(1e-30, double(glm::length(model.model->boundsMax - model.model->boundsMin)));
        for (const SkinnedMesh& mesh : model.meshes) {
            const common::Buffer& posed = scene.meshes[mesh.outputMesh].vertices;
            common::Buffer readback = common::createBuffer(
                device, posed.size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "skinning check");
            VkCommandBuffer cmd = common::beginOneTimeCommands(device);
            VkMemoryBarrier2 written{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                     .srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                     .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                     .dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                     .dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT};
            VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                        .memoryBarrierCount = 1,
                                        .pMemoryBarriers = &written};
            common::vk13.CmdPipelineBarrier2(cmd, &dependency);
            VkBufferCopy region{0, 0, posed.size};
            vkCmdCopyBuffer(cmd, posed.handle, readback.handle, 1, &region);
            VkMemoryBarrier2 copied{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                    .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                    .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                    .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                    .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
            VkDependencyInfo toHost{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                    .memoryBarrierCount = 1,
                                    .pMemoryBarriers = &copied};
            common::vk13.CmdPipelineBarrier2(cmd, &toHost);
            common::submitOneTimeCommands(device, cmd);
            const auto* gpu = static_cast<const common::Vertex*>(readback.mapped);
            for (uint32_t v = 0; v < mesh.vertexCount; ++v) {
                common::SkinnedVertex ref =
                    common::skinVertex(mesh.data->vertices[v], mesh.data->skin[v], pose.joints);
                double position = glm::length(glm::dvec3(gpu[v].position) - ref.position) / size;
                // The angle by atan2 of sine and cosine: acos near 1 would turn the last bit of a
                // float into 0.02 degrees.
                const glm::dvec3 n(gpu[v].normal);
                double normal =
                    glm::degrees(std::atan2(glm::length(glm::cross(n, ref.normal)), glm::dot(n, ref.normal)));
                if (!std::isfinite(position) || !std::isfinite(normal)) position = normal = INFINITY;
                positionErrors.push_back(position);
                maxPosition = std::max(maxPosition, position);
                maxNormal = std::max(maxNormal, normal);
            }
            const auto* guard = reinterpret_cast<const uint8_t*>(gpu + mesh.vertexCount);
            bool intact = true;
            for (size_t b = 0; b < kGuardVertices * sizeof(common::Vertex); ++b)
                intact = intact && guard[b] == 0xFF;
            common::destroyBuffer(device, readback);
            if (!intact)
                throw common::Failure("--check-skinning: the skinning pass wrote past model " +
                                      std::to_string(model.instance) + "'s mesh of " +
                                      std::to_string(mesh.vertexCount) + " vertices");
            checked += mesh.vertexCount;
            ++meshes;
        }
    }
    std::sort(positionErrors.begin(), positionErrors.end());
    double p99 =
        positionErrors[std::min(positionErrors.size() - 1, size_t(double(positionErrors.size()) * 0.99))];
    std::printf(
        "%s: skinning check: %llu vertices in %llu meshes at %.6f s against the double-precision "
        "reference: position error max %.3g, p99 %.3g of the model's size; normal error max %.4f degrees; "
        "guards intact\n",
        chapter, static_cast<unsigned long long>(checked), static_cast<unsigned long long>(meshes),
        pass.posedAt, maxPosition, p99, maxNormal);
    // fp32 arithmetic on coordinates of the model's size: a few units in the last place of 2^-24.
    constexpr double kPositionBound = 1e-5, kNormalBoundDegrees = 0.01;
    if (!(maxPosition <= kPositionBound) || !(maxNormal <= kNormalBoundDegrees))
        throw common::Failure(
            "--check-skinning: the GPU's skinned vertices differ from the reference beyond " +
            std::to_string(kPositionBound) + " of the model's size or " +
            std::to_string(kNormalBoundDegrees) + " degrees");
}

void destroySkinningPass(const common::Device& device, SkinningPass& pass) {
    vkDestroyPipeline(device.handle, pass.pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.pipelineLayout, nullptr);
    vkDestroyDescriptorPool(device.handle, pass.descriptorPool, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, pass.setLayout, nullptr);
    for (common::Buffer& buffer : pass.palettes) common::destroyBuffer(device, buffer);
    for (SkinnedModel& model : pass.models)
        for (SkinnedMesh& mesh : model.meshes)
            if (mesh.ownsInfluences) common::destroyBuffer(device, mesh.influences);
    pass = {};
}

std::string describeSkinning(const SkinningPass& pass) {
    if (pass.models.empty()) return "none (nothing in the scene is animated)";
    uint64_t meshes = 0, vertices = 0;
    for (const SkinnedModel& model : pass.models)
        for (const SkinnedMesh& mesh : model.meshes) ++meshes, vertices += mesh.vertexCount;
    char text[256];
    std::snprintf(
        text, sizeof(text),
        "%zu models, %llu meshes, %llu vertices, %u joints; dispatched in %llu frames (%u dispatches each)",
        pass.models.size(), static_cast<unsigned long long>(meshes),
        static_cast<unsigned long long>(vertices), pass.paletteJoints,
        static_cast<unsigned long long>(pass.dispatchedFrames), pass.dispatches);
    return text;
}
