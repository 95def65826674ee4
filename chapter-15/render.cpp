// chapter-15's Render (render.hpp): the book's Render.java of chapter 15 -- the scene on the GPU,
// the passes created, resized, updated, recorded and destroyed in the book's order.
#include "render.hpp"

#include <cstdio>

#include "common/core/files.hpp"
#include "common/passes/fullscreen.hpp"
#include "gbuffer_layout.hpp"
#include "gpu_types.hpp"

//> passes
// The scene's meshes, materials and textures on the GPU (the book's Render.init), then the passes
// in the order a frame records them.
Render createRender(common::RenderContext& c, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options) {
    Render r;
    r.gpuScene = common::loadGpuScene(c.device, scene, models,
                                      {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true});
    // The book's G-buffer keeps world positions in 16-bit floats: a scene within +-65504.
    common::checkPositionRange(kBookGBuffer.formats, r.gpuScene.boundsMin, r.gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-15: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                r.gpuScene.draws.size(), static_cast<unsigned long long>(r.gpuScene.triangles),
                r.gpuScene.textures.size(), r.gpuScene.materials.size(), scene.lights.size());

    // Pipelines made for this scene: one per material class its materials have, and the light
    // pass's for its lights of each kind (unless --pipelines generic).
    bool generic = common::genericPipelines(options);
    double start = common::millisecondsSinceStart();
    r.scenePass = createScenePass(c.device, c.pipelineCache.handle, c.target.extent, r.gpuScene,
                                  c.framesInFlight, kBookGBuffer, {}, generic);
    r.lightPass = createLightPass(c.device, c.pipelineCache.handle, c.target.extent, r.scenePass.gbuffer,
                                  c.framesInFlight, uint32_t(scene.lights.size()),
                                  {.kinds = generic ? LightKinds{} : lightKinds(shaderLights(scene))});
    r.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, r.lightPass.output);
    r.passesMs = common::millisecondsSinceStart() - start;
    return r;
}

std::vector<std::string> renderPassNames(const Render&) {
    return {"scene", "light", "post"};
}

void destroyRender(common::RenderContext& c, Render& r) {
    common::destroyPostPass(c.device, r.postPass);
    destroyLightPass(c.device, r.lightPass);
    destroyScenePass(c.device, r.scenePass);
    common::destroyGpuScene(c.device, r.gpuScene);
}
//< passes

//> resize
void resizeRender(common::RenderContext& c, Render& r) {
    resizeScenePass(c.device, r.scenePass, c.target.extent);
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
    remakeScenePipelines(c.device, cache, r.scenePass.pipelines, reload, swap);
    common::remakeFullscreenPipeline(c.device, cache, r.lightPass.pipeline, reload, swap);
    common::remakePostPipelines(c.device, cache, r.postPass, reload, swap);
}
//< reload

//> update-frame
// This frame's uniforms: the camera, the lights (they may have moved), the scene info.
void updateRender(common::RenderContext& c, Render& r, uint32_t slot, const FrameView& v) {
    const common::CameraDesc& lens = v.scene.camera;
    glm::mat4 view = common::viewMatrix(v.camera);
    glm::mat4 projection = common::projectionMatrix(lens.fov, c.target.extent, lens.near, lens.far);
    setCamera(r.scenePass, slot, projection, view);
    updateLights(r.lightPass, slot, shaderLights(v.scene),
                 {v.camera.position, v.scene.ambientIntensity, v.scene.ambientColor, 0u});
}
//< update-frame

//> record-frame
// The frame's passes, each timed and labelled (common::timedPass).
void recordRender(common::RenderContext& c, Render& r, common::FrameCommands& f, const FrameView& v) {
    common::timedPass(c, f,
                      [&] { recordScenePass(f.cmd, r.scenePass, r.gpuScene, f.slot, v.camera.position); });
    common::timedPass(c, f, [&] { recordLightPass(f.cmd, r.lightPass, f.slot, v.lightView); });
    common::timedPass(c, f, [&] {
        common::recordPostPass(f.cmd, r.postPass, c.target, f.imageIndex, v.fxaa, c.gui.enabled);
    });
}
//< record-frame
