// chapter-15-lab: the study program built on chapter-15's passes (chapter-15/scene_pass.cpp,
// light_pass.cpp), for what goes beyond the book. With no option it renders what chapter-15
// renders; the options change one thing each, to be measured against the book's renderer:
//   --gbuffer reference|compact (gbuffer_layouts.cpp): the G-buffer in RGBA32F, or in 16 bytes a
//     pixel with the position reconstructed from reversed-Z depth;
//   --light-pass compute (compute_light_pass.cpp): the light pass as a compute dispatch;
//   --light-cutoff, --light-culling tiled (light_culling.cpp): light ranges and tiled culling;
//   --shading forward (forward_shading.cpp): no G-buffer, every fragment lit as it is drawn;
//   --dump (output_dump.cpp): the last frame as PFM files for the accuracy tools;
//   --orbit: the camera turning, for benchmarks that move;
// and the overlay (--gui) switches the G-buffer layout and the light pass's form live.
#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/gpu_types.hpp"
#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/gui_pass.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"
#include "compute_light_pass.hpp"
#include "forward_shading.hpp"
#include "gbuffer_layouts.hpp"
#include "light_culling.hpp"
#include "output_dump.hpp"
#include "shadow_study.hpp"
#include "skinning_study.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-15-lab",
    "chapter-15's renderer with what goes beyond the book: G-buffer layouts, the compute light pass, "
    "light culling, forward shading",
    // The order of shade_pixel.glsl's `view`; "visibility" (--shadows): the sun's visibility alone.
    {"final", "position", "albedo", "normal", "pbr", "depth", "visibility"},
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {{"gbuffer", labLayoutNames(), labLayoutHelp()},
     {"light-pass",
      {"fragment", "compute"},
      "light pass: the book's full-screen triangle, or a compute dispatch (the same shading)"},
     {"dump",
      {},
      "write the light output (and the G-buffer of the float layouts) as PFM files into this directory"},
     {"light-culling",
      {"none", "tiled"},
      "none: every pixel loops over every light (the book's); tiled: over the lights whose range reaches "
      "its 8x8-pixel tile, listed by compute passes each frame"},
     {"light-cutoff",
      {},
      "give each point light without a range the distance where its irradiance falls to this value "
      "(a positive number)"},
     {"orbit", {}, "turn the camera this many degrees (-360..360) about the vertical each frame"},
     {"shading",
      {"deferred", "forward"},
      "deferred: the G-buffer, then the light pass (the book's); "
      "forward: the scene pass shades each fragment with every light (no light pass, the G-buffer "
      "not written), to compare"},
     {"acquire",
      {"early", "late"},
      "early: acquire the image, then record and submit the frame, waiting for the image at colour "
      "output (the book's); late: submit the scene and light passes first, then acquire and submit "
      "the post and GUI passes, which alone wait for the image"},
     common::kGuiClickChoice,
     common::kGuiScaleChoice,
     common::kPipelinesChoice,
     // The shadow study (shadow_study.hpp): chapter-16's cascade shadows, drawn and filtered in
     // other ways.
     {"shadows",
      {"none", "vsm", "pcf2", "pcf3", "pcf5"},
      "the sun's shadow from chapter-16's cascades, for the shadow study: none (chapter-15's light); "
      "the book's variance map; the depth compared by the sampler, filtered over 2x2, 3x3 or 5x5 texels"},
     {"shadow-layers",
      {"geometry", "multiview", "passes"},
      "how --shadows draws the cascades: one pass with the book's geometry shader; one pass with "
      "multiview (a view per cascade); one pass per cascade"},
     {"cascades", {"3", "1", "2", "4"}, "with --shadows: cascades of the sun's shadow map"},
     {"shadow-map-size",
      {"2048", "512", "1024", "4096"},
      "with --shadows: texels along each side of a cascade's map"},
     // The skinning study (skinning_study.hpp): chapter-17's skinning against other forms.
     {"skinning-study",
      {},
      "instead of rendering a scene, skin two generated figures in every form the skinning study "
      "compares, time them and check them against a double-precision reference; write the table "
      "to this CSV file"},
     {"skinning-study-size",
      {"medium", "small", "large"},
      "with --skinning-study: about 66,000 vertices a figure, about a thousand, or about a million"}},
};

//> overlay
// The overlay (--gui): chapter-15's, with the G-buffer layout and the light pass's form in the
// timings window (switched at the next frame).
struct RendererChoice {
    int layout = 0;     // index into labLayouts()
    int lightPass = 0;  // LightPassKind
};

void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa,
                    RendererChoice& renderer, common::LightControls& controls, common::Scene& scene,
                    common::GpuScene& gpuScene, bool deferred, bool switchable) {
    // "visibility" (the last view) only with --shadows, where the overlay has no renderer switch.
    std::vector<std::string> views = kChapter.views;
    if (switchable) views.pop_back();
    common::guiTimingsWindow(
        gui, run, deferred ? views : std::vector<std::string>{"final"}, view,
        {"V  cycles the views", "F  toggles FXAA", common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    if (deferred && switchable) {  // --shading forward has neither; the shadow study, one
        common::guiCombo("G-buffer", labLayoutNames(), &renderer.layout);
        common::guiCombo("light pass", {"fragment", "compute"}, &renderer.lightPass);
    }
    ImGui::End();

    common::beginLightsWindow(controls, scene, gpuScene);
    common::endLightsWindow();
}
//< overlay

// The light pass for a layout and form, with the compute form's pipeline or the tile lists' set.
struct LightPasses {
    LightPass pass;
    ComputeLightPass compute;  // --light-pass compute
};

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

// chapter-16's cascades for a frame's camera and sun, as the shadow study draws them (none
// without a sun).
std::vector<Cascade> studyCascades(const ShadowStudyOptions& study, const common::Scene& scene,
                                   const common::GpuScene& gpuScene, const common::Device& device,
                                   VkExtent2D extent, const glm::mat4& view, int sun) {
    if (sun < 0) return {};
    CascadeCamera cascadeCamera{
        .view = view,
        .fovY = glm::radians(scene.camera.fov),
        .aspect = float(extent.width) / float(extent.height),
        .near = scene.camera.near,
        .far = fittedFar(view, gpuScene.boundsMin, gpuScene.boundsMax, scene.camera.near, scene.camera.far)};
    CascadeSettings settings = study.cascades;
    settings.reachCasters = !device.depthClamp;
    settings.castersMin = gpuScene.boundsMin;
    settings.castersMax = gpuScene.boundsMax;
    return computeCascades(cascadeCamera, scene.lights[size_t(sun)].direction, settings);
}

void run(const common::Options& options) {
    if (skinningStudyRequested(options)) return runSkinningStudy(options);  // no scene, no window
    if (options.choices.count("skinning-study-size"))
        throw common::InputError("--skinning-study-size needs --skinning-study");
    //> setup
    common::ModelCache models;
    common::Scene scene = common::sceneFromOptions(options, models);
    // Light ranges from --light-cutoff, tiled culling, the camera turning.
    LightOptions lightOptions = readLightOptions(options, scene);
    bool forward = readShading(options) == Shading::Forward;
    bool tiled = lightOptions.culling == LightCulling::Tiled;
    ShadowStudyOptions study = readShadowStudy(options);  // --shadows

    common::Target target = common::openTarget(options, "chapter-15-lab");
    common::Instance instance = common::createInstance("chapter-15-lab", options.validation,
                                                       common::targetInstanceExtensions(target));
    common::createTargetSurface(target, instance);
    // chapter-15's features; the shadow study's: chapter-16's geometry shader and depth clamping,
    // or multiview.
    common::Device device =
        common::createDevice(instance, target.surface, options.device,
                             {.dynamicRendering = true,
                              .synchronization2 = true,
                              .scalarBlockLayout = true,
                              .geometryShader = study.enabled && study.layers == ShadowLayers::GeometryShader,
                              .depthClampWhereAvailable = study.enabled,
                              .multiview = study.enabled && study.layers == ShadowLayers::Multiview});
    common::createTargetImages(target, device);
    std::vector<common::FrameSync> frames = common::createFrameSync(device, options.framesInFlight);
    // --acquire late: a second command buffer per frame (from the frame's pool) for the passes that
    // write the acquired image.
    bool acquireLate = options.choices.count("acquire") != 0 && options.choices.at("acquire") == 1;
    std::vector<VkCommandBuffer> lateCommands(frames.size());
    for (size_t i = 0; acquireLate && i < frames.size(); ++i) {
        VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = frames[i].commandPool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
        VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &lateCommands[i]));
        common::nameObject(device.handle, lateCommands[i], "frame " + std::to_string(i) + " late commands");
    }

    // What the first frame's view may cost to rasterise, refused beyond a budget
    // (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(scene, target.extent.width, target.extent.height);
    common::checkFrameCost(scene, models, {&firstView, 1});
    common::GpuScene gpuScene = common::loadGpuScene(
        device, scene, models, {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true});
    if (study.enabled)  // and the study's cascades, which need the scene's bounds
        common::checkFrameCost(
            scene, models,
            cascadeRasterViews(studyCascades(study, scene, gpuScene, device, target.extent,
                                             common::viewMatrix({scene.camera.position, scene.camera.yaw,
                                                                 scene.camera.pitch}),
                                             common::findControlledLights(scene).sun),
                               study.cascades.mapSize));
    models.clear();
    // The book's layout (which the overlay may switch to) keeps world positions in 16-bit floats.
    common::checkPositionRange(kBookGBuffer.formats, gpuScene.boundsMin, gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-15-lab: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                gpuScene.draws.size(), static_cast<unsigned long long>(gpuScene.triangles),
                gpuScene.textures.size(), gpuScene.materials.size(), scene.lights.size());

    common::PipelineCache pipelineCache = common::loadPipelineCache(device, "chapter-15-lab");
    RendererChoice renderer{int(options.choices.count("gbuffer") ? options.choices.at("gbuffer") : 0),
                            int(options.choices.count("light-pass") ? options.choices.at("light-pass") : 0)};
    RendererChoice active = renderer;  // what the passes were made for
    const LabLayout* layout = labLayouts().at(size_t(renderer.layout));
    LightPassKind lightKind = LightPassKind(renderer.lightPass);
    // The scene pass: the layout's G-buffer, or (forward) depth alone with the forward pipelines.
    ScenePass scenePass;
    LightCullingPass culling;  // --light-culling tiled
    LightPasses light;
    ForwardPass forwardPass;  // --shading forward
    ShadowStudy shadowStudy;  // --shadows
    bool generic = common::genericPipelines(options);
    double passesMs = 0.0;  // how long the passes took to make at start-up
    auto createPasses = [&] {
        if (forward) {
            scenePass = createScenePass(device, pipelineCache.handle, target.extent, gpuScene,
                                        options.framesInFlight, kForwardDepthOnly, {}, generic);
            light.pass = createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer,
                                         options.framesInFlight, uint32_t(scene.lights.size()),
                                         {.fragmentShader = ""});
            forwardPass = createForwardPass(device, pipelineCache.handle, scenePass, light.pass);
            return;
        }
        scenePass =
            createScenePass(device, pipelineCache.handle, target.extent, gpuScene, options.framesInFlight,
                            layout->layout, labSceneShaders(*layout), generic);
        if (study.enabled) {  // chapter-16's shadows, and the light pass that reads them
            shadowStudy =
                createShadowStudy(device, pipelineCache.handle, study, scenePass, options.framesInFlight);
            light.pass = createLightPass(device, pipelineCache.handle, target.extent, scenePass.gbuffer,
                                         options.framesInFlight, uint32_t(scene.lights.size()),
                                         {.fragmentShader = shadowLightShader(study, shadowStudy.hardwarePcf),
                                          .moreSets = {shadowStudy.readLayout},
                                          .kinds = generic ? LightKinds{} : lightKinds(shaderLights(scene))});
            return;
        }
        if (tiled)
            culling =
                createLightCulling(device, target.extent, options.framesInFlight, boundedLightCount(scene),
                                   layout->layout, gpuScene.boundsMin, gpuScene.boundsMax);
        light =
            createLightPasses(device, pipelineCache.handle, target.extent, scenePass, *layout, lightKind,
                              options.framesInFlight, uint32_t(scene.lights.size()),
                              generic ? LightKinds{} : lightKinds(shaderLights(scene)), culling.setLayout);
        if (tiled)
            createLightCullingPipelines(
                device, pipelineCache.handle, culling, light.pass,
                std::string("chapter-15-lab/light_cull_bounds") + layout->shaderSuffix + ".comp");
    };
    double passesStart = common::millisecondsSinceStart();
    createPasses();
    passesMs = common::millisecondsSinceStart() - passesStart;
    common::PostPass postPass =
        common::createPostPass(device, pipelineCache.handle, target.format, light.pass.output);

    common::Camera camera{scene.camera.position, scene.camera.yaw, scene.camera.pitch};
    common::CameraInput cameraInput;
    common::LightControls lightControls = common::findControlledLights(scene);
    LightView lightView{.boundsMin = glm::vec4(gpuScene.boundsMin, 0.0f),
                        .boundsMax = glm::vec4(gpuScene.boundsMax, 0.0f),
                        .view = int(options.view),
                        .reversedZ = layout->layout.reversedZ ? 1 : 0};
    bool fxaa = options.switches.count("fxaa") != 0;

    common::Gui gui = common::createGui(options, target);
    common::GuiPass guiPass;
    if (gui.enabled)
        guiPass =
            common::createGuiPass(device, pipelineCache.handle, target.encodedFormat, options.framesInFlight);

    std::vector<std::string> passes{"scene", "light", "post"};
    if (tiled) passes.insert(passes.begin() + 1, "cull");
    if (study.enabled) passes.insert(passes.begin(), "shadow");
    if (forward) passes = {"forward", "post"};
    if (gui.enabled) passes.push_back("gui");
    common::RunControl run = common::createRunControl(options, device, passes);
    //< setup

    auto recreateTarget = [&] {
        if (!common::recreateTargetImages(target, device)) return false;
        resizeScenePass(device, scenePass, target.extent);
        resizeLightPass(device, light.pass, target.extent, scenePass.gbuffer);
        if (light.compute.pipeline) writeComputeOutput(device, light.compute, light.pass);
        if (tiled) resizeLightCulling(device, culling, target.extent);
        common::resizePostPass(device, postPass, light.pass.output);
        // The window may have moved to a screen with other formats: what writes the image follows.
        common::retargetPostPass(device, pipelineCache.handle, postPass, target.format);
        if (gui.enabled) common::retargetGuiPass(device, pipelineCache.handle, guiPass, target.encodedFormat);
        return true;
    };

    auto destroyPasses = [&] {
        if (forward) destroyForwardPass(device, forwardPass);
        if (study.enabled) destroyShadowStudy(device, shadowStudy);
        destroyLightPasses(device, light);
        if (tiled) destroyLightCulling(device, culling);
        destroyScenePass(device, scenePass);
    };

    //> switch-renderer
    // From the overlay: another G-buffer layout or light-pass form, live. Every pass that depends
    // on them is made again (the G-buffer with the scene pass); the scene, the window and the run
    // go on.
    auto switchRenderer = [&] {
        VK_CHECK(vkDeviceWaitIdle(device.handle));
        common::destroyPostPass(device, postPass);
        destroyPasses();
        active = renderer;
        layout = labLayouts().at(size_t(renderer.layout));
        lightKind = LightPassKind(renderer.lightPass);
        createPasses();
        postPass = common::createPostPass(device, pipelineCache.handle, target.format, light.pass.output);
        lightView.reversedZ = layout->layout.reversedZ ? 1 : 0;
        std::printf("chapter-15-lab: switched to the %s G-buffer, %s light pass\n", layout->layout.name,
                    lightKind == LightPassKind::Compute ? "compute" : "fragment");
    };

    // Live reload (common/shaders/shader_watch.hpp): edited shaders compiled and checked; new pipelines for
    // the passes that use them, made while the frames in flight still draw with the old ones,
    // take their place; the old ones go once the GPU is done with those frames. If one cannot be
    // made, none does.
    auto reloadShaders = [&](const common::ShaderReload& reload, uint32_t frame) {
        VkPipelineCache cache = pipelineCache.handle;
        common::PipelineSwap swap;
        try {
            remakeScenePipelines(device, cache, scenePass.pipelines, reload, swap);
            if (study.enabled) remakeShadowStudyPipelines(device, cache, shadowStudy, reload, swap);
            if (forward) remakeScenePipelines(device, cache, forwardPass.pipelines, reload, swap);
            if (tiled) remakeLightCullingPipelines(device, cache, culling, reload, swap);
            common::remakeFullscreenPipeline(device, cache, light.pass.pipeline, reload, swap);
            remakeComputeLightPipeline(device, cache, light.compute, reload, swap);
            common::remakePostPipelines(device, cache, postPass, reload, swap);
            if (gui.enabled)
                common::remakeGuiPipeline(device, cache, guiPass, target.encodedFormat, reload, swap);
        } catch (const std::exception& e) {
            common::discardPipelines(device, swap);
            common::finishShaderReload(e.what());
            return;
        }
        common::swapPipelines(device, swap, frame);  // the old ones go once the frames in flight are done
        common::finishShaderReload();
    };
    //< switch-renderer

    //> frame-loop
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
    float sceneSize = glm::length(gpuScene.boundsMax - gpuScene.boundsMin);
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(run, target, frame);
        if (common::ShaderReload reload = common::pollShaderSources()) reloadShaders(reload, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = frames[slot];

        ImDrawData* overlay = common::drawGui(gui, target, frame, [&] {
            overlayWidgets(gui, run, &lightView.view, &fxaa, renderer, lightControls, scene, gpuScene,
                           !forward, !study.enabled);
        });
        if (renderer.layout != active.layout || renderer.lightPass != active.lightPass) switchRenderer();
        bool keys = !common::guiWantsKeyboard(gui), mouse = !common::guiWantsMouse(gui);
        if (target.window) {  // camera, lights; V cycles the views, F toggles FXAA (unless the GUI has them)
            double now = glfwGetTime();
            float seconds = float(now - lastTime);
            lastTime = now;
            common::moveCamera(target.window, camera, cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
            if (keys)
                common::moveLights(target.window, lightControls, scene, gpuScene, seconds, sceneSize * 0.05f);
            if (common::pressedOnce(target.window, viewKey) && keys && !forward)  // forward: no views
                lightView.view = (lightView.view + 1) % int(kChapter.views.size() - (study.enabled ? 0 : 1));
            if (common::pressedOnce(target.window, fxaaKey) && keys) fxaa = !fxaa;
        }
        camera.yaw += lightOptions.orbitDegrees;  // --orbit: 0 unless asked

        VK_CHECK(vkWaitForFences(device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::releaseRetiredPipelines(device, frame, options.framesInFlight);
        common::collectGpuTimes(run, device, slot);
        uint32_t imageIndex = 0;
        if (!acquireLate) {  // the book's order: the image first
            if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
                if (!recreateTarget()) break;
                continue;
            }
            VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));
        }
        if (gui.enabled) common::updateGuiBuffers(device, guiPass, slot, overlay);

        // This frame's uniforms: camera, lights (they may have moved), scene info.
        glm::mat4 view = common::viewMatrix(camera);
        Projection projection =
            layout->layout.reversedZ && !forward
                ? reversedZProjection(scene, camera, gpuScene, target.extent)
                : Projection{common::projectionMatrix(scene.camera.fov, target.extent, scene.camera.near,
                                                      scene.camera.far),
                             scene.camera.near, scene.camera.far};
        setCamera(scenePass, slot, projection.matrix, view);
        lightView.clipToCameraRelative = glm::inverse(projection.matrix * glm::mat4(glm::mat3(view)));
        lightView.near = projection.near;
        lightView.far = projection.far;
        std::vector<ShaderLight> lights = shaderLights(scene);
        uint32_t unbounded = tiled ? putUnboundedFirst(lights) : 0u;  // tiled culling's order
        updateLights(light.pass, slot, lights,
                     {camera.position, scene.ambientIntensity, scene.ambientColor, 0u});
        if (tiled)
            updateLightCulling(culling, slot, glm::mat4(glm::mat3(view)), projection.matrix, projection.near,
                               unbounded);
        if (study.enabled)  // chapter-16's cascades for this frame's camera and sun (none without a sun)
            updateShadowStudy(
                shadowStudy, slot,
                studyCascades(study, scene, gpuScene, device, target.extent, view, lightControls.sun), view);

        VK_CHECK(vkResetCommandPool(device.handle, sync.commandPool, 0));
        VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
        common::timeFrameStart(run, sync.commandBuffer, slot, frame);
        uint32_t pass = 0;
        if (forward) {  // --shading forward: no G-buffer
            common::beginPass(run, sync.commandBuffer, pass);
            recordForwardPass(sync.commandBuffer, forwardPass, scenePass, light.pass, gpuScene, slot,
                              camera.position);
            common::endPass(run, sync.commandBuffer, slot, pass++);
        } else {
            if (study.enabled) {  // --shadows: chapter-16's order, the shadow pass first
                common::beginPass(run, sync.commandBuffer, pass);
                recordShadowStudy(sync.commandBuffer, shadowStudy, scenePass, gpuScene, slot);
                common::endPass(run, sync.commandBuffer, slot, pass++);
            }
            common::beginPass(run, sync.commandBuffer, pass);
            recordScenePass(sync.commandBuffer, scenePass, gpuScene, slot, camera.position);
            common::endPass(run, sync.commandBuffer, slot, pass++);
            VkDescriptorSet tileLists = tiled ? culling.frames[slot].set : VK_NULL_HANDLE;
            if (tiled) {  // this frame's tile lists, from this frame's G-buffer
                common::beginPass(run, sync.commandBuffer, pass);
                recordLightCulling(sync.commandBuffer, culling, light.pass, slot, lightView);
                common::endPass(run, sync.commandBuffer, slot, pass++);
            }
            common::beginPass(run, sync.commandBuffer, pass);
            if (light.compute.pipeline)
                recordComputeLightPass(sync.commandBuffer, light.compute, light.pass, slot, lightView,
                                       tileLists);
            else if (tiled)
                recordLightPass(sync.commandBuffer, light.pass, slot, lightView, {&tileLists, 1});
            else if (study.enabled)
                recordLightPass(sync.commandBuffer, light.pass, slot, lightView,
                                {&shadowStudy.readSets[slot], 1});
            else
                recordLightPass(sync.commandBuffer, light.pass, slot, lightView);
            common::endPass(run, sync.commandBuffer, slot, pass++);
        }
        // --acquire late: the off-screen passes go to the GPU now, with nothing to wait for; the
        // image is acquired only for the passes that write it, recorded into a second command
        // buffer. (Queue order and the G-buffer's barriers still order the two submits.)
        VkCommandBuffer presentCommands = sync.commandBuffer;
        if (acquireLate) {
            VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
            VkCommandBufferSubmitInfo offscreen{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                                .commandBuffer = sync.commandBuffer};
            VkSubmitInfo2 first{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                                .commandBufferInfoCount = 1,
                                .pCommandBufferInfos = &offscreen};
            VK_CHECK(common::vk13.QueueSubmit2(device.queue, 1, &first, VK_NULL_HANDLE));
            if (!common::acquireTargetImage(target, device, sync.imageAvailable, &imageIndex)) {
                if (!recreateTarget()) break;
                continue;
            }
            VK_CHECK(vkResetFences(device.handle, 1, &sync.inFlight));
            presentCommands = lateCommands[slot];
            VK_CHECK(vkBeginCommandBuffer(presentCommands, &beginInfo));
        }
        common::beginPass(run, presentCommands, pass);
        common::recordPostPass(presentCommands, postPass, target, imageIndex, fxaa, gui.enabled);
        common::endPass(run, presentCommands, slot, pass++);
        if (gui.enabled) {
            common::beginPass(run, presentCommands, pass);
            common::recordGuiPass(presentCommands, guiPass, slot, target, imageIndex, overlay);
            common::endPass(run, presentCommands, slot, pass++);
        }
        VK_CHECK(vkEndCommandBuffer(presentCommands));

        // Every colour write of this batch waits for the image: with one submit (the book's),
        // the G-buffer's and the light output's too, not only the post pass's.
        VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                   .semaphore = sync.imageAvailable,
                                   .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = target.renderFinished[imageIndex],
                                     .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
        VkCommandBufferSubmitInfo commands{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                           .commandBuffer = presentCommands};
        VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = 1,
                             .pWaitSemaphoreInfos = &wait,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &commands,
                             .signalSemaphoreInfoCount = 1,
                             .pSignalSemaphoreInfos = &signal};
        VK_CHECK(common::vk13.QueueSubmit2(device.queue, 1, &submit, sync.inFlight));

        if (lastFrame) common::screenshotLastFrame(run, device, target, imageIndex);
        bool current = common::presentTargetImage(target, device, imageIndex, sync.inFlight);
        common::endFrame(run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget()) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    //< frame-loop
    if (camera.position != scene.camera.position || camera.yaw != scene.camera.yaw ||
        camera.pitch != scene.camera.pitch)
        std::printf("chapter-15-lab: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    camera.position.x, camera.position.y, camera.position.z, camera.yaw, camera.pitch);
    std::vector<std::pair<std::string, std::string>> info =
        common::benchmarkInfo(kChapter, options, device, target, scenePass.formats.depth);
    // What the scene pass allocated: the G-buffer's attachments, depth alone for forward shading.
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(scenePass.formats))});
    common::addPipelineInfo(
        info, scenePass.pipelines.pipelines.size() + forwardPass.pipelines.pipelines.size(), passesMs);
    // Forward shading has no light pass: forward.frag loops over the lights itself.
    info.push_back(
        {"light_pipeline", forward ? "none (forward shading)" : describeLightKinds(light.pass.kinds)});
    if (study.enabled) {
        const char* layers[] = {"geometry shader", "multiview", "a pass per cascade"};
        info.push_back({"shadow_study", shadowFilterName(study.filter) + ", " + layers[int(study.layers)] +
                                            ", " + std::to_string(study.cascades.count) + " cascades of " +
                                            std::to_string(study.cascades.mapSize)});
        if (study.filter != ShadowFilter::Variance)
            info.push_back({"pcf_taps", shadowStudy.hardwarePcf ? "by the sampler (linear depth filtering)"
                                                                : "gathered (no linear depth filtering)"});
    }
    common::reportRun(run, device, info);
    if (gui.enabled)
        std::printf("chapter-15-lab: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    guiPass.growths, guiPass.largestVertices, guiPass.largestIndices);

    if (lightControls.moved) {
        glm::vec3 p =
            lightControls.point >= 0 ? scene.lights[size_t(lightControls.point)].position : glm::vec3(0.0f);
        std::printf("chapter-15-lab: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    lightControls.sunAngle, p.x, p.y, p.z);
    }
    if (tiled) reportLightCulling(culling);
    // The output read back: chapter-15's check, and the PFM files of output_dump.cpp.
    if (options.switches.count("check-output")) checkLightOutput(device, light.pass);
    if (options.values.count("dump"))
        dumpFrame(device, light.pass, scenePass, lightView, options.values.at("dump"), !forward);

    //> teardown
    common::destroyRunControl(device, run);
    if (gui.enabled) common::destroyGuiPass(device, guiPass);
    common::destroyGui(gui);
    common::savePipelineCache(device, pipelineCache);
    common::destroyPostPass(device, postPass);
    destroyPasses();
    common::destroyPipelineCache(device, pipelineCache);
    common::destroyGpuScene(device, gpuScene);
    common::destroyFrameSync(device, frames);
    common::destroyTargetImages(target, device);
    common::destroyDevice(device);
    common::destroyTargetSurface(target, instance);
    common::destroyInstance(instance);
    common::closeTarget(target);
    //< teardown
}

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
