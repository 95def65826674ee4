// chapter-19's GlobalBuffers (chapter-19/global_buffers.cpp): what it writes for a scene -- one
// command per mesh and material with its instances, a group per material, opaque before cut-outs --
// that an empty scene makes nothing, and that a buffer outgrown is made again at twice the need.
#include <gtest/gtest.h>

#include <vector>

#include "chapter-19/global_buffers.hpp"
#include "common/vk/instance.hpp"

namespace {

// Three meshes (3, 6 and 9 indices, addresses that name them), three materials (0 and 2 opaque, 1 a
// cut-out), each material its own class.
common::GpuScene threeMeshes() {
    common::GpuScene scene;
    for (uint32_t m = 0; m < 3; ++m) {
        common::GpuMesh mesh;
        mesh.indexCount = 3 * (m + 1);
        mesh.vertices.address = 0x10000 * (m + 1);
        scene.meshes.push_back(mesh);
        common::GpuMaterial material;
        material.alphaTested = m == 1;
        scene.materials.push_back(material);
    }
    return scene;
}

const std::vector<uint32_t> kClassOf{0, 1, 2};
const std::vector<uint32_t> kFirstIndex{0, 3, 9};  // the meshes' indices one after the other

struct Written {
    std::vector<InstanceData> instances;
    std::vector<VkDrawIndexedIndirectCommand> commands;
    std::vector<IndirectGroup> groups;
};

Written write(const common::GpuScene& scene) {
    std::vector<std::pair<uint32_t, uint32_t>> draws;
    for (uint32_t d : sceneDrawOrder(scene, kClassOf)) draws.push_back({d, 0u});
    Written w;
    w.instances.resize(draws.size());
    w.commands.resize(draws.size());
    uint32_t instances = 0, commands = 0;
    appendCommands(scene, kFirstIndex, draws, w.instances.data(), instances, w.commands.data(), commands,
                   w.groups);
    w.instances.resize(instances);
    w.commands.resize(commands);
    return w;
}

}  // namespace

TEST(GlobalBuffers, OneCommandForAMeshPlacedManyTimes) {
    common::GpuScene scene = threeMeshes();
    for (uint32_t i = 0; i < 1000; ++i) scene.draws.push_back({.mesh = 0, .material = 0});
    Written w = write(scene);
    ASSERT_EQ(w.commands.size(), 1u);
    EXPECT_EQ(w.commands[0].indexCount, 3u);
    EXPECT_EQ(w.commands[0].firstIndex, 0u);
    EXPECT_EQ(w.commands[0].vertexOffset, 0);  // the shader pulls vertex gl_VertexIndex, the index's value
    EXPECT_EQ(w.commands[0].instanceCount, 1000u);
    EXPECT_EQ(w.commands[0].firstInstance, 0u);
    ASSERT_EQ(w.instances.size(), 1000u);
    for (uint32_t i = 0; i < 1000; ++i) {
        EXPECT_EQ(w.instances[i].matrix, i);  // each instance its own draw's matrices
        EXPECT_EQ(w.instances[i].vertices, 0x10000u);
    }
    ASSERT_EQ(w.groups.size(), 1u);
    EXPECT_EQ(w.groups[0].commandCount, 1u);
}

TEST(GlobalBuffers, AGroupPerMaterialOpaqueBeforeCutOuts) {
    common::GpuScene scene = threeMeshes();
    // Interleaved: cut-outs first in the scene's order, meshes shared across materials.
    const uint32_t specs[][2] = {{1, 1}, {0, 0}, {2, 2}, {1, 1}, {0, 2}, {2, 0}, {0, 0}, {1, 2}};
    for (auto [mesh, material] : specs) scene.draws.push_back({.mesh = mesh, .material = material});
    Written w = write(scene);
    // Material 0: meshes 0 (draws 1, 6) and 2 (draw 5); material 2: meshes 0 (4), 1 (7), 2 (2);
    // then the cut-out material 1: mesh 1 (draws 0, 3).
    ASSERT_EQ(w.groups.size(), 3u);
    EXPECT_EQ(w.groups[0].material, 0u);
    EXPECT_EQ(w.groups[1].material, 2u);
    EXPECT_EQ(w.groups[2].material, 1u);
    EXPECT_TRUE(w.groups[2].alphaTested);
    EXPECT_EQ(w.groups[0].commandCount, 2u);
    EXPECT_EQ(w.groups[1].commandCount, 3u);
    EXPECT_EQ(w.groups[2].commandCount, 1u);
    ASSERT_EQ(w.commands.size(), 6u);
    uint32_t expectedFirst = 0;
    for (const VkDrawIndexedIndirectCommand& command : w.commands) {  // the instances follow each other
        EXPECT_EQ(command.firstInstance, expectedFirst);
        expectedFirst += command.instanceCount;
    }
    EXPECT_EQ(expectedFirst, uint32_t(scene.draws.size()));  // every draw once
    for (const IndirectGroup& group : w.groups)
        for (uint32_t c = group.firstCommand; c < group.firstCommand + group.commandCount; ++c)
            for (uint32_t i = 0; i < w.commands[c].instanceCount; ++i) {
                const common::Draw& draw = scene.draws[w.instances[w.commands[c].firstInstance + i].matrix];
                EXPECT_EQ(draw.material, group.material);  // a group draws its material only
                EXPECT_EQ(scene.meshes[draw.mesh].indexCount, w.commands[c].indexCount);
                EXPECT_EQ(kFirstIndex[draw.mesh], w.commands[c].firstIndex);
            }
}

TEST(GlobalBuffers, AnEmptySceneMakesNothing) {
    common::GpuScene scene = threeMeshes();  // no draws
    GlobalBuffers buffers;
    buffers.frames.resize(2);
    common::Device noDevice;  // nothing may be made: a call on it would fail
    updateGlobalBuffers(noDevice, buffers, 0, scene, ScenePass{}, ShadowPlan{});
    EXPECT_EQ(buffers.grown, 0u);
    EXPECT_EQ(buffers.frames[0].matrices.buffer.handle, VK_NULL_HANDLE);
    EXPECT_EQ(buffers.frames[0].instances.buffer.handle, VK_NULL_HANDLE);
    EXPECT_EQ(buffers.frames[0].commands.buffer.handle, VK_NULL_HANDLE);
    EXPECT_TRUE(buffers.frames[0].sceneGroups.empty());
}

// The one path no scene of the chapter's tests reaches (each frame slot's first frame needs the most):
// a buffer outgrown is made again at twice the need, and a frame that fits makes nothing. On the
// device the chapters use (buffers made, nothing submitted: the addresses are the test's own).
TEST(GlobalBuffers, ABufferOutgrownIsMadeAgainAtTwiceTheNeed) {
    common::Instance instance = common::createInstance("unit_tests", false, {});
    common::Device device = common::createDevice(instance, VK_NULL_HANDLE, "llvmpipe",
                                                 {.scalarBlockLayout = true, .bufferDeviceAddress = true});
    common::GpuScene scene = threeMeshes();
    for (uint32_t i = 0; i < 10; ++i) scene.draws.push_back({.mesh = 0, .material = 0});
    ScenePass scenePass;
    scenePass.pipelines.materialClasses.ofMaterial = kClassOf;
    GlobalBuffers buffers;
    buffers.frames.resize(1);
    buffers.indices.firstIndex = kFirstIndex;  // where createSceneIndices would put the meshes
    ShadowPlan plan;
    updateGlobalBuffers(device, buffers, 0, scene, scenePass, plan);
    EXPECT_EQ(buffers.grown, 3u);  // matrices, instances, commands: 4 KiB each at least
    const VkDeviceSize firstInstances = buffers.frames[0].instances.capacity;
    EXPECT_EQ(firstInstances, 4096u);
    // A shadow batch of 1,000 draws: instances and commands outgrown, the matrices not.
    ShadowBatch batch;
    for (uint32_t i = 0; i < 1000; ++i) batch.draws.push_back({i % 10, 1u});
    plan.cached.push_back(batch);
    updateGlobalBuffers(device, buffers, 0, scene, scenePass, plan);
    EXPECT_EQ(buffers.grown, 5u);
    EXPECT_EQ(buffers.frames[0].instances.capacity, 2 * 1010 * sizeof(InstanceData));
    EXPECT_EQ(buffers.frames[0].commands.capacity, 2 * 1010 * sizeof(VkDrawIndexedIndirectCommand));
    EXPECT_EQ(buffers.frames[buffers.lastSlot].shadowInstances, 1000u);
    EXPECT_EQ(buffers.frames[buffers.lastSlot].shadowCommands, 1u);  // one mesh, one material: one command
    const auto* instances = static_cast<const InstanceData*>(buffers.frames[0].instances.buffer.mapped);
    EXPECT_EQ(instances[10 + 999].layers, 1u);  // the shadow instances after the scene's, their cascades kept
    // The same frame again: it fits, nothing is made.
    updateGlobalBuffers(device, buffers, 0, scene, scenePass, plan);
    EXPECT_EQ(buffers.grown, 5u);
    destroyGlobalBuffers(device, buffers);
    common::destroyDevice(device);
    common::destroyInstance(instance);
}
