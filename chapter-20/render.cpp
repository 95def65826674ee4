// chapter-20's Render (render.hpp): chapter-19's, its update and its recording on two threads.
#include "render.hpp"

#include <cstdio>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/gpu_types.hpp"
#include "common/core/files.hpp"
#include "common/passes/fullscreen.hpp"

//> passes
// The scene's meshes, materials and textures on the GPU (the book's Render.init), then the passes
// in the order a frame records them.
Render createRender(common::RenderContext& c, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options) {
    Render r;
    // Every vertex and index buffer made with SHADER_DEVICE_ADDRESS usage: the vertex shaders find
    // them by address (common::Buffer::address). Their memory is allocated with the
    // DEVICE_ADDRESS flag -- any memory type, no dedicated allocation.
    r.gpuScene = common::loadGpuScene(c.device, scene, models,
                                      {.normalMaps = true,
                                       .metalRoughMaps = true,
                                       .occlusionMaps = true,
                                       .skins = true,
                                       .deviceAddresses = true,
                                       .copyableIndices = true});
    // The skinning shader reads the bind pose, the influences and the palette and writes the posed
    // vertices through the addresses each dispatch pushes: no descriptor sets.
    r.skinningPass =
        createSkinningPass(c.device, c.pipelineCache.handle, r.gpuScene, scene, models, c.framesInFlight,
                           {.shader = "chapter-20/skin.comp", .deviceAddresses = true});
    // The book's G-buffer keeps world positions in 16-bit floats: a scene within +-65504.
    common::checkPositionRange(kBookGBuffer.formats, r.gpuScene.boundsMin, r.gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-20: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                r.gpuScene.draws.size(), static_cast<unsigned long long>(r.gpuScene.triangles),
                r.gpuScene.textures.size(), r.gpuScene.materials.size(), scene.lights.size());

    // Pipelines made for this scene, as chapter-18's: the scene and shadow vertex shaders are
    // chapter-19's (they find their draw by gl_InstanceIndex), the fragment shaders chapter-15's and
    // -16's compiled again for the material index's place after the two addresses (CMakeLists.txt).
    bool generic = common::genericPipelines(options);
    r.shadow = shadowOptions(options, c.device);
    double start = common::millisecondsSinceStart();
    r.scenePass = createScenePass(
        c.device, c.pipelineCache.handle, c.target.extent, r.gpuScene, c.framesInFlight, kBookGBuffer,
        {"chapter-20/scene.vert", "chapter-20/scene-indirect.frag"}, generic, kIndirectMeshes);
    r.shadowPass = createShadowPass(c.device, c.pipelineCache.handle, r.shadow.settings, r.shadow.redraw,
                                    r.scenePass, r.gpuScene, c.framesInFlight,
                                    {.vertex = "chapter-20/shadow.vert",
                                     .geometry = "chapter-20/shadow.geom",
                                     .fragment = "chapter-20/shadow-indirect.frag"});
    r.lightPass = createLightPass(c.device, c.pipelineCache.handle, c.target.extent, r.scenePass.gbuffer,
                                  c.framesInFlight, uint32_t(scene.lights.size()),
                                  {.fragmentShader = "chapter-20/light.frag",
                                   .moreSets = {r.shadowPass.readLayout},
                                   .kinds = generic ? LightKinds{} : lightKinds(shaderLights(scene))});
    r.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, r.lightPass.output);
    r.passesMs = common::millisecondsSinceStart() - start;
    // Every mesh's indices in one buffer (the posed meshes' too: after the skinning pass made them).
    r.globalBuffers = createGlobalBuffers(c.device, r.gpuScene, c.framesInFlight);
    r.snapshots.resize(c.framesInFlight);
    return r;
}

std::vector<std::string> renderPassNames(const Render& r) {
    std::vector<std::string> passes{"shadow", "scene", "light", "post"};
    if (!r.skinningPass.models.empty())
        passes.insert(passes.begin(), "skinning");  // only where something moves
    return passes;
}

void destroyRender(common::RenderContext& c, Render& r) {
    destroyGlobalBuffers(c.device, r.globalBuffers);
    common::destroyPostPass(c.device, r.postPass);
    destroyLightPass(c.device, r.lightPass);
    destroyShadowPass(c.device, r.shadowPass);
    destroySkinningPass(c.device, r.skinningPass);
    destroyScenePass(c.device, r.scenePass);
    common::destroyGpuScene(c.device, r.gpuScene);
}
//< passes

//> resize
void resizeRender(common::RenderContext& c, Render& r) {
    resizeScenePass(c.device, r.scenePass, c.target.extent);
    invalidateShadowCache(r.shadowPass, r.shadow.redraw);  // every cascade drawn whole again
    // A frame written for the old size is written again (frame_threads.cpp): its pose too.
    r.skinningPass.stale = true;
    resizeLightPass(c.device, r.lightPass, c.target.extent, r.scenePass.gbuffer);
    common::resizePostPass(c.device, r.postPass, r.lightPass.output);
    // The window may have moved to a screen with other formats: what writes the image follows.
    common::retargetPostPass(c.device, c.pipelineCache.handle, r.postPass, c.target.format);
}
//< resize

//> reload
void remakeRenderPipelines(common::RenderContext& c, Render& r, const common::ShaderReload& reload,
                           common::PipelineSwap& swap) {
    VkPipelineCache cache = c.pipelineCache.handle;
    remakeSkinningPipeline(c.device, cache, r.skinningPass, reload, swap);
    remakeShadowPipelines(c.device, cache, r.shadowPass, reload, swap);
    remakeScenePipelines(c.device, cache, r.scenePass.pipelines, reload, swap);
    common::remakeFullscreenPipeline(c.device, cache, r.lightPass.pipeline, reload, swap);
    common::remakePostPipelines(c.device, cache, r.postPass, reload, swap);
}
//< reload

//> frame-cascades
std::vector<Cascade> frameCascades(Render& r, VkExtent2D extent, const FrameView& v) {
    if (v.sun < 0) return {};
    const common::CameraDesc& lens = v.scene.camera;
    glm::mat4 view = common::viewMatrix(v.camera);
    float far = lens.far;
    if (r.shadow.fitFar) far = fittedFar(view, r.gpuScene.boundsMin, r.gpuScene.boundsMax, lens.near, far);
    r.shadow.settings.castersMin = r.gpuScene.boundsMin;  // the casters: the scene, marker included
    r.shadow.settings.castersMax = r.gpuScene.boundsMax;
    CascadeCamera camera{.view = view,
                         .fovY = glm::radians(lens.fov),
                         .aspect = float(extent.width) / float(extent.height),
                         .near = lens.near,
                         .far = far};
    return computeCascades(camera, v.scene.lights[size_t(v.sun)].direction, r.shadow.settings);
}
//< frame-cascades

//> update-frame
// The main thread, once the slot's fence has signalled: the slot's uniforms (the camera, the
// cascades, the lights), its palette, its GlobalBuffers and its snapshot -- chapter-19's update, the
// shadow plan kept with the slot.
void updateRender(common::RenderContext& c, Render& r, uint32_t slot, const FrameView& v,
                  const std::function<void()>& waitForRender) {
    const common::CameraDesc& lens = v.scene.camera;
    glm::mat4 view = common::viewMatrix(v.camera);
    glm::mat4 projection = common::projectionMatrix(lens.fov, c.target.extent, lens.near, lens.far);
    setCamera(r.scenePass, slot, projection, view);
    float lastFar = r.cascades.empty() ? 0.0f : r.cascades.back().splitFar;
    r.cascades = frameCascades(r, c.target.extent, v);
    if (lastFar > 0.0f && !r.cascades.empty() && r.cascades.back().splitFar != lastFar)
        ++r.farSteps[r.cascades.back().splitFar > lastFar ? 0 : 1];
    poseSkinnedModels(r.skinningPass, r.gpuScene, v.clock, slot);
    // The moving casters' map is made while no frame is recorded (the light pass's sets name it),
    // and the light pipeline made again then too.
    if (updateCascades(c.device, r.shadowPass, slot, r.cascades, view, r.gpuScene, waitForRender))
        common::respecializeFullscreenPipeline(c.device, c.pipelineCache.handle, r.lightPass.pipeline,
                                               kMovingCastersConstant, VK_TRUE);
    updateLights(r.lightPass, slot, shaderLights(v.scene),
                 {v.camera.position, v.scene.ambientIntensity, v.scene.ambientColor, 0u});
    // What recording reads of this update goes with the slot: the plan (the slot's GlobalBuffers
    // point into its batches), the camera's position, the view shown.
    FrameSnapshot& snapshot = r.snapshots[slot];
    snapshot.shadowPlan = std::move(r.shadowPass.plan);
    snapshot.cameraPosition = v.camera.position;
    snapshot.lightView = v.lightView;
    snapshot.fxaa = v.fxaa;
    updateGlobalBuffers(c.device, r.globalBuffers, slot, r.gpuScene, r.scenePass, snapshot.shadowPlan);
}
//< update-frame

//> record-frame
// The render thread: chapter-19's passes, reading of what changes only the frame's slot.
void recordRender(common::RenderContext& c, Render& r, common::FrameCommands& f) {
    const FrameSnapshot& snapshot = r.snapshots[f.slot];
    if (!r.skinningPass.models.empty())
        common::timedPass(c, f, [&] { recordSkinningPass(f.cmd, r.skinningPass, f.slot); });
    common::timedPass(c, f, [&] {
        recordShadowPass(f.cmd, r.shadowPass, snapshot.shadowPlan, r.scenePass, r.gpuScene, f.slot,
                         [&](VkCommandBuffer cmd, const std::vector<ShadowDraw>& draws, VkPipeline& bound) {
                             recordIndirectShadowBatch(cmd, r.globalBuffers, f.slot, r.shadowPass,
                                                       r.scenePass, draws, bound);
                         });
    });
    common::timedPass(c, f, [&] {
        recordScenePass(
            f.cmd, r.scenePass, r.gpuScene, f.slot, snapshot.cameraPosition,
            [&](VkCommandBuffer cmd) { recordIndirectScene(cmd, r.globalBuffers, f.slot, r.scenePass); });
    });
    VkDescriptorSet shadows = r.shadowPass.readSets[f.slot];
    common::timedPass(c, f, [&] {
        recordLightPass(f.cmd, r.lightPass, f.slot, snapshot.lightView, {&shadows, 1});
    });
    common::timedPass(c, f, [&] {
        common::recordPostPass(f.cmd, r.postPass, c.target, f.imageIndex, snapshot.fxaa, c.gui.enabled);
    });
}
//< record-frame
