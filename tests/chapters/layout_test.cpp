// layout_test SHADER.spv: C++ and GLSL agree on the layout of every struct chapter-15 (and the
// lab, chapter-15-lab) shares with its shaders. C++ fills two ShaderLights, a ShaderSceneInfo, two
// ShaderMaterials, a CameraUniform, a DrawConstants and the lab's CullView (in buffers of the
// layouts the programs use) and a LightView (as push constants) with distinct values; a compute
// shader that includes the same gpu_types.glsl and cull_view.glsl reads them and writes each
// field back; every field must come back
// as written. A wrong size or offset on either side puts some other field's value there. Exit 0
// when all agree.
#include <cstdio>
#include <cstring>
#include <vector>

#include "../tools/gpu_compute.hpp"
#include "chapter-15-lab/light_culling.hpp"  // CullView
#include "chapter-15/gpu_types.hpp"
#include "common/app/cli.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/passes/camera_frames.hpp"
#include "common/scene/camera.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"

namespace {

const char* gShaderPath = nullptr;

void run(const common::Options& options) {
    ShaderLight lights[2] = {{{1, 2, 3}, 1u, 4, {5, 6, 7}, 37}, {{8, 9, 10}, 0u, 11, {12, 13, 14}, 38}};
    ShaderSceneInfo scene{{15, 16, 17}, 18, {19, 20, 21}, 22u};
    ShaderMaterial materials[2] = {{{23, 24, 25, 26}, 27, 28, 35u, 40, 41, 42, {0, 0}},
                                   {{29, 30, 31, 32}, 33, 34, 36u, 43, 44, 45, {0, 0}}};
    std::vector<float> expected;
    for (const ShaderLight& l : lights)
        expected.insert(expected.end(), {l.position.x, l.position.y, l.position.z, float(l.directional),
                                         l.intensity, l.color.x, l.color.y, l.color.z, l.range});
    expected.insert(expected.end(), {scene.cameraPosition.x, scene.cameraPosition.y, scene.cameraPosition.z,
                                     scene.ambientIntensity, scene.ambientColor.x, scene.ambientColor.y,
                                     scene.ambientColor.z, float(scene.lightCount)});
    for (const ShaderMaterial& m : materials)
        expected.insert(expected.end(),
                        {m.diffuse.x, m.diffuse.y, m.diffuse.z, m.diffuse.w, m.roughness, m.metallic,
                         float(m.flags), m.alphaCutoff, m.normalScale, m.occlusionStrength});
    // Matrices: every element a distinct value, read back column by column.
    float next = 100.0f;
    auto fill = [&](float* values, int count) {
        for (int k = 0; k < count; ++k) values[k] = next++;
    };
    common::CameraUniform camera;
    fill(&camera.projection[0][0], 16);
    fill(&camera.view[0][0], 16);
    DrawConstants draw;
    fill(&draw.model[0][0], 16);
    for (glm::vec4& column : draw.normalMatrix) fill(&column[0], 3), column.w = 0.0f;
    LightView view;
    fill(&view.clipToCameraRelative[0][0], 16);
    fill(&view.boundsMin[0], 4);
    fill(&view.boundsMax[0], 4);
    view.view = 7;
    view.near = next++;
    view.far = next++;
    view.reversedZ = 1;
    auto columns = [&](const float* values, int count, int rows, int stride) {
        for (int c = 0; c < count; ++c)
            for (int r = 0; r < rows; ++r) expected.push_back(values[c * stride + r]);
    };
    columns(&camera.projection[0][0], 4, 4, 4);
    columns(&camera.view[0][0], 4, 4, 4);
    columns(&draw.model[0][0], 4, 4, 4);
    columns(&draw.normalMatrix[0][0], 3, 3, 4);
    columns(&view.clipToCameraRelative[0][0], 4, 4, 4);
    columns(&view.boundsMin[0], 1, 4, 4);
    columns(&view.boundsMax[0], 1, 4, 4);
    expected.insert(expected.end(), {float(view.view), view.near, view.far, float(view.reversedZ)});
    CullView cull;
    fill(&cull.viewRotation[0][0], 16);
    cull.projectionScale = {next, next + 1};
    cull.near = next + 2;
    cull.margin = next + 3;
    cull.tileCount = {uint32_t(next + 4), uint32_t(next + 5)};
    cull.extent = {uint32_t(next + 6), uint32_t(next + 7)};
    cull.capacity = uint32_t(next + 8);
    cull.unboundedLights = uint32_t(next + 9);
    columns(&cull.viewRotation[0][0], 4, 4, 4);
    expected.insert(expected.end(),
                    {cull.projectionScale.x, cull.projectionScale.y, cull.near, cull.margin,
                     float(cull.tileCount.x), float(cull.tileCount.y), float(cull.extent.x),
                     float(cull.extent.y), float(cull.capacity), float(cull.unboundedLights)});

    common::Instance instance = common::createInstance("layout_test", options.validation, {});
    common::Device device =
        common::createDevice(instance, VK_NULL_HANDLE, options.device, {.scalarBlockLayout = true});
    VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    common::Buffer buffers[7] = {
        common::createBuffer(device, sizeof(lights), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, host, "lights"),
        common::createBuffer(device, sizeof(scene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, host, "scene"),
        common::createBuffer(device, sizeof(materials), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, host,
                             "materials"),
        common::createBuffer(device, sizeof(camera), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, host, "camera"),
        common::createBuffer(device, sizeof(draw), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, host, "draw"),
        common::createBuffer(device, expected.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             host, "results"),
        common::createBuffer(device, sizeof(cull), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, host, "cull"),
    };
    std::memcpy(buffers[0].mapped, lights, sizeof(lights));
    std::memcpy(buffers[1].mapped, &scene, sizeof(scene));
    std::memcpy(buffers[2].mapped, materials, sizeof(materials));
    std::memcpy(buffers[3].mapped, &camera, sizeof(camera));
    std::memcpy(buffers[4].mapped, &draw, sizeof(draw));
    std::memcpy(buffers[6].mapped, &cull, sizeof(cull));
    std::memset(buffers[5].mapped, 0xff, expected.size() * sizeof(float));  // NaN until written

    runCompute(device, gShaderPath,
               {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[0].handle},
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffers[1].handle},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[2].handle},
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffers[3].handle},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[4].handle},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[5].handle},
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffers[6].handle}},
               &view, sizeof(view), 1);

    const float* fields = static_cast<const float*>(buffers[5].mapped);
    size_t wrong = 0;
    for (size_t i = 0; i < expected.size(); ++i)
        if (fields[i] != expected[i]) {
            std::printf("field %zu: the shader read %g, C++ wrote %g\n", i, fields[i], expected[i]);
            ++wrong;
        }
    std::printf(
        "%zu fields of ShaderLight, ShaderSceneInfo, ShaderMaterial, CameraUniform, DrawConstants, "
        "LightView and CullView checked, %zu disagree\n",
        expected.size(), wrong);

    for (common::Buffer& buffer : buffers) common::destroyBuffer(device, buffer);
    common::destroyDevice(device);
    common::destroyInstance(instance);
    if (wrong != 0) throw common::Failure("C++ and GLSL disagree on the struct layouts");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: layout_test SHADER.spv [--validation] [--device NAME]\n");
        return 2;
    }
    gShaderPath = argv[1];
    argv[1] = argv[0];  // the rest is the usual command line
    return common::runChapter(argc - 1, argv + 1, {"layout_test", "C++/GLSL struct layout agreement", {}},
                              run);
}
