// chapter-15-lab's Render (render.hpp): chapter-15's, with a branch wherever a study changes it.
#include "render.hpp"

#include <cstdio>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/gpu_types.hpp"
#include "common/app/light_controls.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/passes/fullscreen.hpp"
#include "common/scene/frame_cost.hpp"

LabStudies readLabStudies(const common::Options& options, common::Scene& scene) {
    LabStudies s;
    s.lights = readLightOptions(options, scene);
    s.forward = readShading(options) == Shading::Forward;
    s.tiled = s.lights.culling == LightCulling::Tiled;
    s.study = readShadowStudy(options);
    s.generic = common::genericPipelines(options);
    return s;
}

namespace {

LightPasses createLightPasses(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                              const ScenePass& scenePass, const LabLayout& layout, LightPassKind kind,
                              uint32_t framesInFlight, uint32_t lightCount, LightKinds kinds,
                              VkDescriptorSetLayout tileLists) {
    LightPasses passes;
    bool tiled = tileLists != VK_NULL_HANDLE;
    if (tiled) kinds = {};  // the tile lists pick the lights: chapter-15's loops are not used
    // With tile lists, the culling passes (compute) read sets 0-2 too.
    VkShaderStageFlags culling = tiled ? VK_SHADER_STAGE_COMPUTE_BIT : 0;
    if (kind == LightPassKind::Compute) {
        LightPassSetup setup = computeLightPassSetup();
        setup.kinds = kinds;
        passes.pass =
            createLightPass(device, cache, extent, scenePass.gbuffer, framesInFlight, lightCount, setup);
        passes.compute = createComputeLightPass(device, cache, passes.pass,
                                                labLightShader(layout, "comp", tiled), tileLists);
        return passes;
    }
    LightPassSetup setup{.fragmentShader = labLightShader(layout, "frag", tiled),
                         .stages = VK_SHADER_STAGE_FRAGMENT_BIT | culling,
                         .kinds = kinds};
    if (tiled) setup.moreSets = {tileLists};  // set 3
    passes.pass =
        createLightPass(device, cache, extent, scenePass.gbuffer, framesInFlight, lightCount, setup);
    return passes;
}

void destroyLightPasses(const common::Device& device, LightPasses& passes) {
    if (passes.compute.pipeline) destroyComputeLightPass(device, passes.compute);
    destroyLightPass(device, passes.pass);
}

// The passes the studies ask for (all but the post pass, which switchRenderer makes again after them).
void createPasses(common::RenderContext& c, Render& r, const common::Scene& scene) {
    const LabStudies& s = r.studies;
    VkPipelineCache cache = c.pipelineCache.handle;
    uint32_t lights = uint32_t(scene.lights.size());
    if (s.forward) {  // --shading forward: depth alone, and the forward pipelines
        r.scenePass = createScenePass(c.device, cache, c.target.extent, r.gpuScene, c.framesInFlight,
                                      kForwardDepthOnly, {}, s.generic);
        r.light.pass = createLightPass(c.device, cache, c.target.extent, r.scenePass.gbuffer,
                                       c.framesInFlight, lights, {.fragmentShader = ""});
        r.forwardPass = createForwardPass(c.device, cache, r.scenePass, r.light.pass);
        return;
    }
    r.scenePass = createScenePass(c.device, cache, c.target.extent, r.gpuScene, c.framesInFlight,
                                  r.layout->layout, labSceneShaders(*r.layout), s.generic);
    LightKinds kinds = s.generic ? LightKinds{} : lightKinds(shaderLights(scene));
    if (s.study.enabled) {  // chapter-16's shadows, and the light pass that reads them
        r.shadowStudy = createShadowStudy(c.device, cache, s.study, r.scenePass, c.framesInFlight);
        r.light.pass =
            createLightPass(c.device, cache, c.target.extent, r.scenePass.gbuffer, c.framesInFlight, lights,
                            {.fragmentShader = shadowLightShader(s.study, r.shadowStudy.hardwarePcf),
                             .moreSets = {r.shadowStudy.readLayout},
                             .kinds = kinds});
        return;
    }
    if (s.tiled)
        r.culling = createLightCulling(c.device, c.target.extent, c.framesInFlight, boundedLightCount(scene),
                                       r.layout->layout, r.gpuScene.boundsMin, r.gpuScene.boundsMax);
    r.light = createLightPasses(c.device, cache, c.target.extent, r.scenePass, *r.layout, r.lightKind,
                                c.framesInFlight, lights, kinds, r.culling.setLayout);
    if (s.tiled)
        createLightCullingPipelines(
            c.device, cache, r.culling, r.light.pass,
            std::string("chapter-15-lab/light_cull_bounds") + r.layout->shaderSuffix + ".comp");
}

void destroyPasses(common::RenderContext& c, Render& r) {
    if (r.studies.forward) destroyForwardPass(c.device, r.forwardPass);
    if (r.studies.study.enabled) destroyShadowStudy(c.device, r.shadowStudy);
    destroyLightPasses(c.device, r.light);
    if (r.studies.tiled) destroyLightCulling(c.device, r.culling);
    destroyScenePass(c.device, r.scenePass);
}

}  // namespace

std::vector<Cascade> studyCascades(const Render& r, const common::Device& device, VkExtent2D extent,
                                   const common::Scene& scene, const glm::mat4& view, int sun) {
    if (sun < 0) return {};
    const common::CameraDesc& lens = scene.camera;
    CascadeCamera cascadeCamera{
        .view = view,
        .fovY = glm::radians(lens.fov),
        .aspect = float(extent.width) / float(extent.height),
        .near = lens.near,
        .far = fittedFar(view, r.gpuScene.boundsMin, r.gpuScene.boundsMax, lens.near, lens.far)};
    CascadeSettings settings = r.studies.study.cascades;
    settings.reachCasters = !device.depthClamp;
    settings.castersMin = r.gpuScene.boundsMin;
    settings.castersMax = r.gpuScene.boundsMax;
    return computeCascades(cascadeCamera, scene.lights[size_t(sun)].direction, settings);
}

// The scene on the GPU, then the passes for the options' layout and light-pass form.
Render createRender(common::RenderContext& c, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options, const LabStudies& studies) {
    Render r;
    r.studies = studies;
    r.gpuScene = common::loadGpuScene(c.device, scene, models,
                                      {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true});
    if (studies.study.enabled) {  // what the study's cascades may cost, which needs the scene's bounds
        glm::mat4 view = common::viewMatrix({scene.camera.position, scene.camera.yaw, scene.camera.pitch});
        int sun = common::findControlledLights(scene).sun;
        common::checkFrameCost(
            scene, models,
            cascadeRasterViews(studyCascades(r, c.device, c.target.extent, scene, view, sun),
                               studies.study.cascades.mapSize));
    }
    // The book's layout (which the overlay may switch to) keeps world positions in 16-bit floats.
    common::checkPositionRange(kBookGBuffer.formats, r.gpuScene.boundsMin, r.gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-15-lab: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                r.gpuScene.draws.size(), static_cast<unsigned long long>(r.gpuScene.triangles),
                r.gpuScene.textures.size(), r.gpuScene.materials.size(), scene.lights.size());

    auto chosen = [&](const char* name) {
        auto found = options.choices.find(name);
        return found == options.choices.end() ? 0 : int(found->second);
    };
    r.active = {chosen("gbuffer"), chosen("light-pass")};
    r.layout = labLayouts().at(size_t(r.active.layout));
    r.lightKind = LightPassKind(r.active.lightPass);
    double start = common::millisecondsSinceStart();
    createPasses(c, r, scene);
    r.passesMs = common::millisecondsSinceStart() - start;
    r.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, r.light.pass.output);
    return r;
}

std::vector<std::string> renderPassNames(const Render& r) {
    if (r.studies.forward) return {"forward", "post"};
    std::vector<std::string> passes{"scene", "light", "post"};
    if (r.studies.tiled) passes.insert(passes.begin() + 1, "cull");
    if (r.studies.study.enabled) passes.insert(passes.begin(), "shadow");
    return passes;
}

//> switch-renderer
void switchRenderer(common::RenderContext& c, Render& r, const RendererChoice& choice,
                    const common::Scene& scene, LightView& lightView) {
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
    common::destroyPostPass(c.device, r.postPass);
    destroyPasses(c, r);
    r.active = choice;
    r.layout = labLayouts().at(size_t(choice.layout));
    r.lightKind = LightPassKind(choice.lightPass);
    createPasses(c, r, scene);
    r.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, r.light.pass.output);
    lightView.reversedZ = r.layout->layout.reversedZ ? 1 : 0;
    std::printf("chapter-15-lab: switched to the %s G-buffer, %s light pass\n", r.layout->layout.name,
                r.lightKind == LightPassKind::Compute ? "compute" : "fragment");
}
//< switch-renderer

//> resize
void resizeRender(common::RenderContext& c, Render& r) {
    resizeScenePass(c.device, r.scenePass, c.target.extent);
    resizeLightPass(c.device, r.light.pass, c.target.extent, r.scenePass.gbuffer);
    if (r.light.compute.pipeline) writeComputeOutput(c.device, r.light.compute, r.light.pass);
    if (r.studies.tiled) resizeLightCulling(c.device, r.culling, c.target.extent);
    common::resizePostPass(c.device, r.postPass, r.light.pass.output);
    // The window may have moved to a screen with other formats: what writes the image follows.
    common::retargetPostPass(c.device, c.pipelineCache.handle, r.postPass, c.target.format);
}
//< resize

//> reload
void remakeRenderPipelines(common::RenderContext& c, Render& r, const common::ShaderReload& reload,
                           common::PipelineSwap& swap) {
    VkPipelineCache cache = c.pipelineCache.handle;
    remakeScenePipelines(c.device, cache, r.scenePass.pipelines, reload, swap);
    if (r.studies.study.enabled) remakeShadowStudyPipelines(c.device, cache, r.shadowStudy, reload, swap);
    if (r.studies.forward) remakeScenePipelines(c.device, cache, r.forwardPass.pipelines, reload, swap);
    if (r.studies.tiled) remakeLightCullingPipelines(c.device, cache, r.culling, reload, swap);
    common::remakeFullscreenPipeline(c.device, cache, r.light.pass.pipeline, reload, swap);
    remakeComputeLightPipeline(c.device, cache, r.light.compute, reload, swap);
    common::remakePostPipelines(c.device, cache, r.postPass, reload, swap);
}
//< reload

//> update-frame
// This frame's uniforms: camera (reversed-Z for the layouts that store it), lights (they may have
// moved), scene info; the tile lists' view; the shadow study's cascades.
void updateRender(common::RenderContext& c, Render& r, uint32_t slot, const FrameView& v) {
    const common::CameraDesc& lens = v.scene.camera;
    glm::mat4 view = common::viewMatrix(v.camera);
    Projection projection =
        r.layout->layout.reversedZ && !r.studies.forward
            ? reversedZProjection(v.scene, v.camera, r.gpuScene, c.target.extent)
            : Projection{common::projectionMatrix(lens.fov, c.target.extent, lens.near, lens.far), lens.near,
                         lens.far};
    setCamera(r.scenePass, slot, projection.matrix, view);
    v.lightView.clipToCameraRelative = glm::inverse(projection.matrix * glm::mat4(glm::mat3(view)));
    v.lightView.near = projection.near;
    v.lightView.far = projection.far;
    std::vector<ShaderLight> lights = shaderLights(v.scene);
    uint32_t unbounded = r.studies.tiled ? putUnboundedFirst(lights) : 0u;  // tiled culling's order
    updateLights(r.light.pass, slot, lights,
                 {v.camera.position, v.scene.ambientIntensity, v.scene.ambientColor, 0u});
    if (r.studies.tiled)
        updateLightCulling(r.culling, slot, glm::mat4(glm::mat3(view)), projection.matrix, projection.near,
                           unbounded);
    if (r.studies.study
            .enabled)  // chapter-16's cascades for this frame's camera and sun (none without a sun)
        updateShadowStudy(r.shadowStudy, slot,
                          studyCascades(r, c.device, c.target.extent, v.scene, view, v.sun), view);
}
//< update-frame

//> record-frame
void recordRender(common::RenderContext& c, Render& r, common::FrameCommands& f, const FrameView& v) {
    if (r.studies.forward) {  // --shading forward: no G-buffer
        common::timedPass(c, f, [&] {
            recordForwardPass(f.cmd, r.forwardPass, r.scenePass, r.light.pass, r.gpuScene, f.slot,
                              v.camera.position);
        });
        return;
    }
    if (r.studies.study.enabled)  // --shadows: chapter-16's order, the shadow pass first
        common::timedPass(c, f,
                          [&] { recordShadowStudy(f.cmd, r.shadowStudy, r.scenePass, r.gpuScene, f.slot); });
    common::timedPass(c, f,
                      [&] { recordScenePass(f.cmd, r.scenePass, r.gpuScene, f.slot, v.camera.position); });
    VkDescriptorSet tileLists = r.studies.tiled ? r.culling.frames[f.slot].set : VK_NULL_HANDLE;
    if (r.studies.tiled)  // this frame's tile lists, from this frame's G-buffer
        common::timedPass(c, f,
                          [&] { recordLightCulling(f.cmd, r.culling, r.light.pass, f.slot, v.lightView); });
    common::timedPass(c, f, [&] {
        if (r.light.compute.pipeline)
            recordComputeLightPass(f.cmd, r.light.compute, r.light.pass, f.slot, v.lightView, tileLists);
        else if (r.studies.tiled)
            recordLightPass(f.cmd, r.light.pass, f.slot, v.lightView, {&tileLists, 1});
        else if (r.studies.study.enabled)
            recordLightPass(f.cmd, r.light.pass, f.slot, v.lightView, {&r.shadowStudy.readSets[f.slot], 1});
        else
            recordLightPass(f.cmd, r.light.pass, f.slot, v.lightView);
    });
}

void recordPresent(common::RenderContext& c, Render& r, common::FrameCommands& f, const FrameView& v) {
    common::timedPass(c, f, [&] {
        common::recordPostPass(f.cmd, r.postPass, c.target, f.imageIndex, v.fxaa, c.gui.enabled);
    });
}
//< record-frame

void addRenderInfo(std::vector<std::pair<std::string, std::string>>& info, const Render& r) {
    // What the scene pass allocated: the G-buffer's attachments, depth alone for forward shading.
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(r.scenePass.formats))});
    common::addPipelineInfo(
        info, r.scenePass.pipelines.pipelines.size() + r.forwardPass.pipelines.pipelines.size(), r.passesMs);
    // Forward shading has no light pass: forward.frag loops over the lights itself.
    info.push_back({"light_pipeline",
                    r.studies.forward ? "none (forward shading)" : describeLightKinds(r.light.pass.kinds)});
    const ShadowStudyOptions& study = r.studies.study;
    if (study.enabled) {
        const char* layers[] = {"geometry shader", "multiview", "a pass per cascade"};
        info.push_back({"shadow_study", shadowFilterName(study.filter) + ", " + layers[int(study.layers)] +
                                            ", " + std::to_string(study.cascades.count) + " cascades of " +
                                            std::to_string(study.cascades.mapSize)});
        if (study.filter == ShadowFilter::Pcf2 || study.filter == ShadowFilter::Pcf3 ||
            study.filter == ShadowFilter::Pcf5)
            info.push_back({"pcf_taps", r.shadowStudy.hardwarePcf ? "by the sampler (linear depth filtering)"
                                                                  : "gathered (no linear depth filtering)"});
    }
}

void destroyRender(common::RenderContext& c, Render& r) {
    common::destroyPostPass(c.device, r.postPass);
    destroyPasses(c, r);
    common::destroyGpuScene(c.device, r.gpuScene);
}
