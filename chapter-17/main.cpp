// chapter-17: animations -- the book's chapter 17 in C++.
//
// chapter-16's frame with skinned, animated models: before the shadow pass, a compute pass
// (skinning_pass.cpp, shaders/chapter-17/skin.comp) poses every animated model's skinned meshes
// into vertex buffers of their own, which the shadow and scene passes then draw like any static
// mesh -- one skinning serves every cascade and the scene. The joints are posed on the CPU by
// time (common/model/animation.hpp: glTF's STEP, LINEAR and CUBICSPLINE samplers, the book's key
// frames with interpolation). chapter-16's passes, unchanged:
//   shadow pass (chapter-16/shadow_pass.cpp): the sun's cascades, a moving figure drawn apart;
//   scene pass (chapter-15/scene_pass.cpp): the G-buffer;
//   light pass (chapter-15/light_pass.cpp, chapter-16's light.frag): Cook-Torrance and shadows;
//   post pass and GUI pass (common/passes/).
// What this chapter adds to chapter-16's main.cpp: the animation clock (advanceClock, the
// overlay's animation controls, Space), the skinning pass recorded first (recordFrame), and
// --animation-time and --check-skinning. run() at the end is the chapter in four steps.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/gpu_types.hpp"
#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "chapter-16/cascades.hpp"
#include "chapter-16/shadow_pass.hpp"
#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/run_control.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/fullscreen.hpp"
#include "common/passes/gui_pass.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"
#include "skinning_pass.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-17",
    "animations: skinned models posed by a compute pass before chapter-16's passes (the book's chapter 17)",
    // The order of shade_pixel.glsl's `view`, then light.frag's own.
    {"final", "position", "albedo", "normal", "pbr", "depth", "shadow-map", "cascades", "visibility"},
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     {"check-skinning",
      "read the skinned vertices back after the last frame and compare them with a double-precision "
      "reference; fail beyond the bound"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {{"animation-time",
      {},
      "SECONDS: pose every animation at this time and keep it there (screenshots, tests); else they "
      "play from 0, by the clock in a window and 1/60 s a frame headless"},
     common::kGuiClickChoice,
     common::kGuiScaleChoice,
     common::kPipelinesChoice,
     {"cascades", {"3", "1", "2", "4"}, "cascades of the sun's shadow map (the book's: 3)"},
     {"shadow-map-size", {"2048", "512", "1024", "4096"}, "texels along each side of a cascade's shadow map"},
     {"shadow-far",
      {"scene", "view"},
      "where the last cascade ends: where the scene's bounds end (in steps), or the view's far plane"},
     {"shadow-redraw",
      {"scrolled", "scrolled-together", "changed", "always"},
      "what a frame draws of the shadow map: only the bands a cascade's move exposed, moving casters "
      "drawn apart (scrolled); the same with moving casters in the cached map (scrolled-together); a "
      "cascade whole when what it sees changed (changed); every cascade every frame (always)"},
     {"camera-motion",
      {"still", "walk", "creep", "turn", "jump"},
      "(testing, benchmarks) move the camera every frame: walk 2 cm forward, creep 0.1 mm, turn 0.5 "
      "degrees about y, jump: walk, and every 8th frame 5 m forward or back"},
     {"light-motion",
      {"still", "walk", "walk-stop"},
      "(testing, benchmarks) move the point light (and its marker) 5 cm a frame toward the camera, "
      "level; walk-stop: for the first 30 frames only"}},
};

//> chapter-state
// Everything the chapter makes, in the order setUp() makes it (tearDown() destroys it in
// reverse), and what the frames change.
struct Chapter {
    common::Scene scene;
    common::ModelCache models;  // the models' CPU data: the skinning pass poses their rigs
    common::Target target;
    common::Instance instance;
    common::Device device;
    std::vector<common::FrameSync> frames;
    common::GpuScene gpuScene;
    common::PipelineCache pipelineCache;
    ScenePass scenePass;
    SkinningPass skinningPass;
    ShadowPass shadowPass;
    LightPass lightPass;
    common::PostPass postPass;
    common::Gui gui;  // --gui: Dear ImGui's context and input (common/app/gui.cpp) and its pass
    common::GuiPass guiPass;
    common::RunControl run;  // --frames, --resize, --benchmark (each pass timed), --screenshot
    // What the frames change.
    common::Camera camera;
    common::CameraInput cameraInput;
    common::LightControls lightControls;
    AnimationClock clock;
    LightView lightView;
    bool fxaa = false;
    bool genericPipelines = false;                 // --pipelines generic
    CascadeSettings cascadeSettings;               // --cascades, --shadow-map-size
    bool fitFar = true;                            // --shadow-far scene
    ShadowRedraw redraw = ShadowRedraw::Scrolled;  // --shadow-redraw
    uint32_t cameraMotion = 0;                     // --camera-motion: still, walk, creep, turn, jump
    uint32_t lightMotion = 0;                      // --light-motion: still, walk, walk-stop
    uint32_t farSteps[2]{};                        // how often the fitted far plane stepped up and down
    std::vector<Cascade> cascades;                 // this frame's
    double passesMs = 0.0;                 // how long createPasses took at start-up (pipelines, mostly)
    std::vector<uint64_t> firstFrameCost;  // fragments bound: the view, then each cascade
};
//< chapter-state

// The cascades for a frame's camera and sun, over the view from near to where the scene ends
// (--shadow-far scene) or to the far plane; none without a directional light.
std::vector<Cascade> frameCascades(Chapter& c, const glm::mat4& view) {
    if (c.lightControls.sun < 0) return {};
    float far = c.scene.camera.far;
    if (c.fitFar) far = fittedFar(view, c.gpuScene.boundsMin, c.gpuScene.boundsMax, c.scene.camera.near, far);
    c.cascadeSettings.castersMin = c.gpuScene.boundsMin;  // the casters: the scene, marker included
    c.cascadeSettings.castersMax = c.gpuScene.boundsMax;
    CascadeCamera camera{.view = view,
                         .fovY = glm::radians(c.scene.camera.fov),
                         .aspect = float(c.target.extent.width) / float(c.target.extent.height),
                         .near = c.scene.camera.near,
                         .far = far};
    return computeCascades(camera, c.scene.lights[size_t(c.lightControls.sun)].direction, c.cascadeSettings);
}

//> update-frame
// This frame's uniforms: the camera, the cascades, the lights (they may have moved), the scene info.
void updateFrame(Chapter& c, uint32_t slot) {
    glm::mat4 view = common::viewMatrix(c.camera);
    glm::mat4 projection = common::projectionMatrix(c.scene.camera.fov, c.target.extent, c.scene.camera.near,
                                                    c.scene.camera.far);
    setCamera(c.scenePass, slot, projection, view);
    // The cascades for this frame's camera and sun, over the view from near to where the scene
    // ends (--shadow-far scene) or to the far plane. Without a directional light there are none:
    // every pixel's visibility is 1.
    // What the shadow pass draws of them (shadow_cache.hpp): what the cascades' moves exposed and
    // where casters moved, unless --shadow-redraw says more.
    float lastFar = c.cascades.empty() ? 0.0f : c.cascades.back().splitFar;
    c.cascades = frameCascades(c, view);
    if (lastFar > 0.0f && !c.cascades.empty() && c.cascades.back().splitFar != lastFar)
        ++c.farSteps[c.cascades.back().splitFar > lastFar ? 0 : 1];
    // The animated models posed at this frame's time (their bounds, for the cascades' culling).
    poseSkinnedModels(c.skinningPass, c.gpuScene, c.clock, slot);
    // The first time a caster moves, the light pipeline is made again to read the moving casters'
    // map too (until then a still scene pays nothing for it).
    if (updateCascades(c.device, c.shadowPass, slot, c.cascades, view, c.gpuScene))
        common::respecializeFullscreenPipeline(c.device, c.pipelineCache.handle, c.lightPass.pipeline,
                                               kMovingCastersConstant, VK_TRUE);
    updateLights(c.lightPass, slot, shaderLights(c.scene),
                 {c.camera.position, c.scene.ambientIntensity, c.scene.ambientColor, 0u});
}
//< update-frame

//> record-frame
// The frame's passes into one command buffer, each labelled for graphics debuggers and timed for
// --benchmark.
void recordFrame(Chapter& c, common::FrameSync& sync, uint32_t slot, uint32_t frame, uint32_t imageIndex,
                 ImDrawData* overlay) {
    VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
    VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
    common::timeFrameStart(c.run, sync.commandBuffer, slot, frame);
    // First the skinning (none when nothing is animated; no dispatch when no pose changed), then
    // chapter-16's passes, which draw the posed vertices as they draw every mesh. `pass` counts
    // the timed passes, in the order createRunControl was given them.
    uint32_t pass = 0;
    if (!c.skinningPass.models.empty()) {
        common::beginPass(c.run, sync.commandBuffer, pass);
        recordSkinningPass(sync.commandBuffer, c.skinningPass, slot);
        common::endPass(c.run, sync.commandBuffer, slot, pass++);
    }
    common::beginPass(c.run, sync.commandBuffer, pass);
    recordShadowPass(sync.commandBuffer, c.shadowPass, c.scenePass, c.gpuScene, slot);
    common::endPass(c.run, sync.commandBuffer, slot, pass++);
    common::beginPass(c.run, sync.commandBuffer, pass);
    recordScenePass(sync.commandBuffer, c.scenePass, c.gpuScene, slot, c.camera.position);
    common::endPass(c.run, sync.commandBuffer, slot, pass++);
    common::beginPass(c.run, sync.commandBuffer, pass);
    VkDescriptorSet shadows = c.shadowPass.readSets[slot];
    recordLightPass(sync.commandBuffer, c.lightPass, slot, c.lightView, {&shadows, 1});
    common::endPass(c.run, sync.commandBuffer, slot, pass++);
    common::beginPass(c.run, sync.commandBuffer, pass);
    common::recordPostPass(sync.commandBuffer, c.postPass, c.target, imageIndex, c.fxaa, c.gui.enabled);
    common::endPass(c.run, sync.commandBuffer, slot, pass++);
    if (c.gui.enabled) {
        common::beginPass(c.run, sync.commandBuffer, pass);
        common::recordGuiPass(sync.commandBuffer, c.guiPass, slot, c.target, imageIndex, overlay);
        common::endPass(c.run, sync.commandBuffer, slot, pass);
    }
    VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));
}
//< record-frame

// The shadow controls of the overlay: the book's cascade debug view (a switch in its settings
// file), where the last cascade ends, whether cascades are drawn only when they changed; and per
// cascade, the slice it covers, its texel in the world and how often it was drawn.
struct ShadowControls {
    bool* fitFar;
    ShadowRedraw* redraw;
    const std::vector<Cascade>& cascades;
    ShadowPass& pass;
};

void shadowWidgets(int* view, const ShadowControls& shadows) {
    ImGui::Separator();
    ImGui::TextUnformatted("Shadows");
    bool debug = *view == 7;
    if (ImGui::Checkbox("show cascades", &debug)) *view = debug ? 7 : 0;
    ImGui::Checkbox("fit last cascade to the scene", shadows.fitFar);
    int form = int(*shadows.redraw);
    if (ImGui::Combo("redraw", &form, "scrolled\0scrolled-together\0changed\0always\0")) {
        *shadows.redraw = ShadowRedraw(form);
        invalidateShadowCache(shadows.pass, *shadows.redraw);
    }
    const ShadowCache& cache = shadows.pass.cache;
    for (size_t i = 0; i < shadows.cascades.size(); ++i) {
        const Cascade& cascade = shadows.cascades[i];
        ImGui::Text("cascade %zu: %.2f..%.2f m, texel %.1f mm, drawn %llu times", i, cascade.splitNear,
                    cascade.splitFar, cascade.texel * 1000.0f,
                    static_cast<unsigned long long>(cache.redraws[i]));
    }
}

// The animation controls of the overlay: play and pause (Space), the clip, the speed and the
// time (dragging it pauses); what the skinning pass did.
void animationWidgets(AnimationClock& clock, const SkinningPass& pass) {
    ImGui::Separator();
    ImGui::TextUnformatted("Animation");
    if (pass.models.empty()) {
        ImGui::TextUnformatted("nothing in the scene is animated");
        return;
    }
    ImGui::Checkbox("play (Space)", &clock.playing);
    int clips = 0;
    for (const SkinnedModel& model : pass.models) clips = std::max(clips, int(model.model->rig.clips.size()));
    if (clips > 1) ImGui::SliderInt("clip", &clock.clip, 0, clips - 1);
    ImGui::SliderFloat("speed", &clock.speed, 0.0f, 4.0f, "%.2fx");
    double duration = 0.0;
    for (const SkinnedModel& model : pass.models) {
        const common::Rig& rig = model.model->rig;
        if (!rig.clips.empty())
            duration = std::max(duration,
                                rig.clips[size_t(std::min(clock.clip, int(rig.clips.size()) - 1))].duration);
    }
    float seconds = float(duration > 0.0 ? std::fmod(clock.seconds, duration) : 0.0);
    if (ImGui::SliderFloat("time", &seconds, 0.0f, float(duration), "%.3f s")) {
        clock.seconds = seconds;
        clock.playing = false;
    }
    ImGui::Text("%zu animated models; %llu vertices skinned a frame", pass.models.size(),
                static_cast<unsigned long long>(pass.vertices));
}

//> overlay
// The overlay (--gui): the timings window with the view selector (common/app/gui.cpp) and FXAA; a
// second window with chapter-15's light controls, the ambient light, the shadow controls and the
// animation controls.
void overlayWidgets(common::Gui& gui, const common::RunControl& run, int* view, bool* fxaa,
                    common::LightControls& controls, common::Scene& scene, common::GpuScene& gpuScene,
                    const ShadowControls& shadows, AnimationClock& clock, const SkinningPass& skinning) {
    common::guiTimingsWindow(
        gui, run, kChapter.views, view,
        {"V  cycles the views", "F  toggles FXAA", "Space  plays or pauses the animations",
         common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", fxaa);
    ImGui::End();

    common::beginLightsWindow(controls, scene, gpuScene);
    shadowWidgets(view, shadows);
    animationWidgets(clock, skinning);
    common::endLightsWindow();
}
//< overlay

//> book-scene
// --book-scene: the book's chapter 17 changes chapter 16's scene (its Main.java): no tree, and Bob
// (the md5 model "boblamp", converted by the book's ModelGenerator) at the origin, scaled 0.04 and
// turned -90 degrees about y; the camera at (-5, 3, 0), turned as in chapter 16; the sun straight
// down at intensity 8; no point light. Bob is read from the clone's
// booksamples/chapter-17/resources/models/bob/boblamp.json (common/model/book_model.hpp).
void useBookChapter17Scene(common::Scene& scene, const std::filesystem::path& bookScene) {
    scene.camera.position = {-5.0f, 3.0f, 0.0f};
    scene.camera.yaw = 90.0f;
    scene.camera.pitch = -20.0f;
    scene.camera.near = 0.5f;
    scene.camera.far = 50.0f;
    scene.lights = {common::Light{
        .type = common::Light::Type::Directional, .direction = {0.0f, -1.0f, 0.0f}, .intensity = 8.0f}};
    scene.models.resize(1);  // Sponza; the point light's marker goes with the light
    std::error_code ec;
    std::filesystem::path given =
        std::filesystem::weakly_canonical(std::filesystem::absolute(bookScene, ec), ec);
    std::filesystem::path samples =
        std::filesystem::is_directory(given, ec)
            ? given / "booksamples"
            : given.parent_path().parent_path().parent_path().parent_path().parent_path();
    std::filesystem::path bob = samples / "chapter-17" / "resources" / "models" / "bob" / "boblamp.json";
    if (!std::filesystem::is_regular_file(bob, ec)) {
        common::warn("the book's Bob is not at " + common::utf8(bob) + ": the scene without him");
        return;
    }
    common::ModelInstance bobInstance{.file = bob};
    bobInstance.transform.scale = glm::vec3(0.04f);
    bobInstance.transform.rotation = {0.0f, -90.0f, 0.0f};
    scene.models.push_back(bobInstance);
}
//< book-scene

//> passes
// The passes, in the order a frame records them.
void createPasses(Chapter& c, uint32_t framesInFlight) {
    // Pipelines made for this scene: one per material class its materials have, and the light
    // pass's for its lights of each kind (unless --pipelines generic). The scene shaders are
    // chapter-15's, the shadow and light shaders chapter-16's, all compiled into chapter-17's folder
    // (CMakeLists.txt).
    c.scenePass =
        createScenePass(c.device, c.pipelineCache.handle, c.target.extent, c.gpuScene, framesInFlight,
                        kBookGBuffer, {"chapter-17/scene.vert", "chapter-17/scene.frag"}, c.genericPipelines);
    c.shadowPass = createShadowPass(c.device, c.pipelineCache.handle, c.cascadeSettings, c.redraw,
                                    c.scenePass, c.gpuScene, framesInFlight,
                                    {.vertex = "chapter-17/shadow.vert",
                                     .geometry = "chapter-17/shadow.geom",
                                     .fragment = "chapter-17/shadow.frag"});
    c.lightPass =
        createLightPass(c.device, c.pipelineCache.handle, c.target.extent, c.scenePass.gbuffer,
                        framesInFlight, uint32_t(c.scene.lights.size()),
                        {.fragmentShader = "chapter-17/light.frag",
                         .moreSets = {c.shadowPass.readLayout},
                         .kinds = c.genericPipelines ? LightKinds{} : lightKinds(shaderLights(c.scene))});
    c.postPass =
        common::createPostPass(c.device, c.pipelineCache.handle, c.target.format, c.lightPass.output);
    if (c.gui.enabled)
        c.guiPass =
            common::createGuiPass(c.device, c.pipelineCache.handle, c.target.encodedFormat, framesInFlight);
}

void destroyPasses(Chapter& c) {
    if (c.gui.enabled) common::destroyGuiPass(c.device, c.guiPass);
    common::destroyPostPass(c.device, c.postPass);
    destroyLightPass(c.device, c.lightPass);
    destroyShadowPass(c.device, c.shadowPass);
    destroySkinningPass(c.device, c.skinningPass);
    destroyScenePass(c.device, c.scenePass);
}

// Live reload (common/shaders/shader_watch.hpp): edited shaders compiled and checked. New pipelines for
// the passes that use them are made from the new code while the frames in flight still draw
// with the old ones; then the new ones take their place, and the old ones are destroyed once
// the GPU is done with those frames. If one cannot be made, none does: the old pipelines keep
// drawing, and the error is shown.
void reloadShaders(Chapter& c, const common::ShaderReload& reload, uint32_t frame) {
    VkPipelineCache cache = c.pipelineCache.handle;
    common::PipelineSwap swap;
    try {
        remakeSkinningPipeline(c.device, cache, c.skinningPass, reload, swap);
        remakeShadowPipelines(c.device, cache, c.shadowPass, reload, swap);
        remakeScenePipelines(c.device, cache, c.scenePass.pipelines, reload, swap);
        common::remakeFullscreenPipeline(c.device, cache, c.lightPass.pipeline, reload, swap);
        common::remakePostPipelines(c.device, cache, c.postPass, reload, swap);
        if (c.gui.enabled)
            common::remakeGuiPipeline(c.device, cache, c.guiPass, c.target.encodedFormat, reload, swap);
    } catch (const std::exception& e) {
        common::discardPipelines(c.device, swap);
        common::finishShaderReload(e.what());
        return;
    }
    common::swapPipelines(c.device, swap, frame);  // the old ones go once the frames in flight are done
    common::finishShaderReload();
}
//< passes

// --animation-time SECONDS: a number from 0 to 10^9 (about 32 years), nothing else.
double animationTime(const std::string& text) {
    char* end = nullptr;
    double seconds = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(seconds) || seconds < 0.0 ||
        seconds > 1e9)
        throw common::InputError("--animation-time must be a number of seconds from 0 to 1e9, got '" + text +
                                 "'");
    return seconds;
}

//> setup
void setUp(Chapter& c, const common::Options& options) {
    common::ModelCache& models = c.models;
    // The default scene with chapter-17's figures (scenes/figures.hpp), unless another is given.
    if (options.scene.empty() && options.model.empty() && options.bookScene.empty())
        c.scene = common::loadSceneFile(common::executableDir() / "scenes" / "default" / "animated.json");
    else
        c.scene = common::sceneFromOptions(options, models);
    if (!options.bookScene.empty()) useBookChapter17Scene(c.scene, options.bookScene);

    c.target = common::openTarget(options, "chapter-17: animations");
    c.instance =
        common::createInstance("chapter-17", options.validation, common::targetInstanceExtensions(c.target));
    common::createTargetSurface(c.target, c.instance);
    // What this chapter adds: geometryShader (the shadow pass sends each triangle to every
    // cascade's layer) and depthClamp where the device has it (casters in front of a cascade's box
    // kept); the rest is chapter-15's.
    c.device = common::createDevice(c.instance, c.target.surface, options.device,
                                    {.dynamicRendering = true,
                                     .synchronization2 = true,
                                     .scalarBlockLayout = true,
                                     .geometryShader = true,
                                     .depthClampWhereAvailable = true});
    common::createTargetImages(c.target, c.device);
    c.frames = common::createFrameSync(c.device, options.framesInFlight);

    c.pipelineCache = common::loadPipelineCache(c.device, "chapter-17");
    // Skinned meshes uploaded as they are stored, for the skinning pass to pose; each animated
    // model's draws then draw vertex buffers of their own (skinning_pass.cpp).
    c.gpuScene = common::loadGpuScene(
        c.device, c.scene, models,
        {.normalMaps = true, .metalRoughMaps = true, .occlusionMaps = true, .skins = true});
    c.skinningPass = createSkinningPass(c.device, c.pipelineCache.handle, c.gpuScene, c.scene, models,
                                        options.framesInFlight);
    // The book's G-buffer keeps world positions in 16-bit floats: a scene within +-65504.
    common::checkPositionRange(kBookGBuffer.formats, c.gpuScene.boundsMin, c.gpuScene.boundsMax,
                               common::utf8(options.scene.empty() ? options.model : options.scene));
    std::printf("chapter-17: %zu draws, %llu triangles, %zu textures, %zu materials, %zu lights\n",
                c.gpuScene.draws.size(), static_cast<unsigned long long>(c.gpuScene.triangles),
                c.gpuScene.textures.size(), c.gpuScene.materials.size(), c.scene.lights.size());

    c.gui = common::createGui(options, c.target);
    c.genericPipelines = common::genericPipelines(options);
    auto chosen = [&](const char* name) {
        auto found = options.choices.find(name);
        return found == options.choices.end() ? 0u : found->second;
    };
    const uint32_t kCascadeCounts[] = {3, 1, 2, 4}, kMapSizes[] = {2048, 512, 1024, 4096};
    c.cascadeSettings = {.count = kCascadeCounts[chosen("cascades")],
                         .mapSize = kMapSizes[chosen("shadow-map-size")]};
    c.fitFar = chosen("shadow-far") == 0;
    // No depth clamping on this device: the cascades reach toward the sun as far as the scene does
    // (its bounds, updateFrame).
    c.cascadeSettings.reachCasters = !c.device.depthClamp;
    c.cameraMotion = chosen("camera-motion");
    c.lightMotion = chosen("light-motion");
    c.redraw = ShadowRedraw(chosen("shadow-redraw"));
    double passesStart = common::millisecondsSinceStart();
    createPasses(c, options.framesInFlight);
    c.passesMs = common::millisecondsSinceStart() - passesStart;
    std::vector<std::string> passes{"shadow", "scene", "light", "post"};
    if (!c.skinningPass.models.empty())
        passes.insert(passes.begin(), "skinning");  // only where something moves
    if (c.gui.enabled) passes.push_back("gui");
    c.run = common::createRunControl(options, c.device, passes);

    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.lightControls = common::findControlledLights(c.scene);
    c.lightView = {.boundsMin = glm::vec4(c.gpuScene.boundsMin, 0.0f),
                   .boundsMax = glm::vec4(c.gpuScene.boundsMax, 0.0f),
                   .view = int(options.view),
                   .near = c.scene.camera.near,
                   .far = c.scene.camera.far};
    c.fxaa = options.switches.count("fxaa") != 0;
    if (auto time = options.values.find("animation-time"); time != options.values.end()) {
        c.clock.seconds = animationTime(time->second);
        c.clock.playing = false;
    }

    // What the first frame may cost to rasterise -- the view and every cascade, each triangle
    // drawn into each layer -- refused beyond a budget (common/scene/frame_cost.hpp).
    std::vector<common::RasterView> views{
        common::sceneRasterView(c.scene, c.target.extent.width, c.target.extent.height)};
    for (const common::RasterView& cascade :
         cascadeRasterViews(frameCascades(c, common::viewMatrix(c.camera)), c.cascadeSettings.mapSize))
        views.push_back(cascade);
    c.firstFrameCost = common::checkFrameCost(c.scene, models, views).fragments;
}
//< setup

//> resize
// The window changed size: the swapchain, then every image of the window's size.
bool recreateTarget(Chapter& c) {
    if (!common::recreateTargetImages(c.target, c.device)) return false;
    resizeScenePass(c.device, c.scenePass, c.target.extent);
    invalidateShadowCache(c.shadowPass, c.redraw);  // every cascade drawn whole again
    resizeLightPass(c.device, c.lightPass, c.target.extent, c.scenePass.gbuffer);
    common::resizePostPass(c.device, c.postPass, c.lightPass.output);
    // The window may have moved to a screen with other formats: what writes the image follows.
    common::retargetPostPass(c.device, c.pipelineCache.handle, c.postPass, c.target.format);
    if (c.gui.enabled)
        common::retargetGuiPass(c.device, c.pipelineCache.handle, c.guiPass, c.target.encodedFormat);
    return true;
}
//< resize

// The keys (unless the overlay has them): the camera, the lights; V cycles the views, F toggles FXAA.
void handleInput(Chapter& c, double& lastTime, common::KeyPress& viewKey, common::KeyPress& fxaaKey,
                 common::KeyPress& playKey) {
    if (!c.target.window) return;
    bool keys = !common::guiWantsKeyboard(c.gui), mouse = !common::guiWantsMouse(c.gui);
    double now = glfwGetTime();
    float seconds = float(now - lastTime);
    lastTime = now;
    float sceneSize = glm::length(c.gpuScene.boundsMax - c.gpuScene.boundsMin);
    common::moveCamera(c.target.window, c.camera, c.cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
    if (keys)
        common::moveLights(c.target.window, c.lightControls, c.scene, c.gpuScene, seconds, sceneSize * 0.05f);
    if (common::pressedOnce(c.target.window, viewKey) && keys)
        c.lightView.view = (c.lightView.view + 1) % int(kChapter.views.size());
    if (common::pressedOnce(c.target.window, fxaaKey) && keys) c.fxaa = !c.fxaa;
    if (common::pressedOnce(c.target.window, playKey) && keys)
        c.clock.playing = !c.clock.playing;  // the book's Space
}

// The animation clock, once a frame: by the wall clock in a window (the book advances a key frame
// per frame, so its speed follows the frame rate), by 1/60 s a frame headless and in benchmarks,
// so that runs repeat exactly.
void advanceClock(Chapter& c, uint32_t frame, double& lastTime) {
    double now = common::millisecondsSinceStart() / 1000.0;
    double seconds = c.target.window && !c.run.benchmark ? now - lastTime : 1.0 / 60.0;
    lastTime = now;
    if (c.clock.playing && frame > 0) c.clock.seconds += std::min(seconds, 0.25) * double(c.clock.speed);
}

// --camera-motion and --light-motion: the camera and the point light moved by fixed steps each
// frame, for the tests and benchmarks of the shadow cache.
void moveForTesting(Chapter& c, uint32_t frame) {
    glm::vec3 forward = common::cameraForward(c.camera);
    switch (c.cameraMotion) {
        case 1:
            c.camera.position += forward * 0.02f;
            break;  // walk
        case 2:
            c.camera.position += forward * 1e-4f;
            break;  // creep
        case 3:
            c.camera.yaw += 0.5f;
            break;  // turn
        case 4:     // jump
            c.camera.position += forward * 0.02f;
            if (frame % 8 == 7) c.camera.position += forward * (frame % 16 == 7 ? 5.0f : -5.0f);
            break;
        default:
            break;
    }
    bool lightWalks = c.lightMotion == 1 || (c.lightMotion == 2 && frame < 30);
    if (lightWalks && c.lightControls.point >= 0) {
        glm::vec3 step = glm::normalize(glm::vec3(forward.x, 0.0f, forward.z) + glm::vec3(1e-6f, 0.0f, 0.0f));
        glm::vec3 position = c.scene.lights[size_t(c.lightControls.point)].position - step * 0.05f;
        common::placePointLight(c.lightControls, c.scene, c.gpuScene, position);
    }
}

//> frame-loop
void frameLoop(Chapter& c, const common::Options& options) {
    double lastTime = glfwGetTime();
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F}, playKey{GLFW_KEY_SPACE};
    double clockTime = common::millisecondsSinceStart() / 1000.0;
    for (uint32_t frame = 0;;) {
        bool lastFrame = common::beginFrame(c.run, c.target, frame);
        if (common::ShaderReload reload = common::pollShaderSources()) reloadShaders(c, reload, frame);
        uint32_t slot = frame % options.framesInFlight;
        common::FrameSync& sync = c.frames[slot];
        ImDrawData* overlay = common::drawGui(c.gui, c.target, frame, [&] {
            overlayWidgets(c.gui, c.run, &c.lightView.view, &c.fxaa, c.lightControls, c.scene, c.gpuScene,
                           {&c.fitFar, &c.redraw, c.cascades, c.shadowPass}, c.clock, c.skinningPass);
        });
        handleInput(c, lastTime, viewKey, fxaaKey, playKey);

        // Wait until this slot's previous frame is done, then acquire the image to present.
        VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
        common::releaseRetiredPipelines(c.device, frame, options.framesInFlight);
        common::collectGpuTimes(c.run, c.device, slot);
        uint32_t imageIndex = 0;
        if (!common::acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
            if (!recreateTarget(c)) break;
            continue;
        }
        VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));
        if (c.gui.enabled) common::updateGuiBuffers(c.device, c.guiPass, slot, overlay);

        moveForTesting(c, frame);
        advanceClock(c, frame, clockTime);
        updateFrame(c, slot);
        recordFrame(c, sync, slot, frame, imageIndex, overlay);

        // One submit: wait for the acquired image before writing colour, signal when done.
        VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                   .semaphore = sync.imageAvailable,
                                   .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
        VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = c.target.renderFinished[imageIndex],
                                     .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
        VkCommandBufferSubmitInfo commands{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                           .commandBuffer = sync.commandBuffer};
        VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = 1,
                             .pWaitSemaphoreInfos = &wait,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &commands,
                             .signalSemaphoreInfoCount = 1,
                             .pSignalSemaphoreInfos = &signal};
        VK_CHECK(common::vk13.QueueSubmit2(c.device.queue, 1, &submit, sync.inFlight));

        if (lastFrame) common::screenshotLastFrame(c.run, c.device, c.target, imageIndex);
        bool current = common::presentTargetImage(c.target, c.device, imageIndex, sync.inFlight);
        common::endFrame(c.run, frame);
        if (lastFrame) break;
        if (!current && !recreateTarget(c)) break;
        ++frame;
    }
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
}
//< frame-loop

// A row per cascade for --benchmark's report (the shadow pass draws them all at once, so the GPU
// times them together, on the "shadow" row): the slice it covers, its texel's size in the world,
// in how many frames it was drawn (and drawn whole), and what it cost a frame on average: texels
// cleared and drawn, draws and triangles submitted.
std::vector<std::pair<std::string, std::string>> describeCascades(const Chapter& c) {
    std::vector<std::pair<std::string, std::string>> rows;
    const ShadowCache& cache = c.shadowPass.cache;
    double frames = double(std::max<uint64_t>(cache.frames, 1));
    for (size_t i = 0; i < c.cascades.size(); ++i) {
        const Cascade& cascade = c.cascades[i];
        char text[256];
        std::snprintf(
            text, sizeof(text),
            "%.2f..%.2f m, texel %.2f mm, drawn in %llu of %llu frames (%llu whole); a frame: "
            "%.0f texels, %.1f draws, %.0f triangles",
            cascade.splitNear, cascade.splitFar, cascade.texel * 1000.0f,
            static_cast<unsigned long long>(cache.redraws[i]), static_cast<unsigned long long>(cache.frames),
            static_cast<unsigned long long>(cache.wholeRedraws[i]), double(cache.texels[i]) / frames,
            double(cache.draws[i]) / frames, double(cache.triangles[i]) / frames);
        rows.push_back({"shadow_cascade_" + std::to_string(i), text});
    }
    return rows;
}

// What the skinning pass had to do, and did: for the report and --benchmark.
std::string describeSkinning(const Chapter& c) {
    const SkinningPass& pass = c.skinningPass;
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

// --check-output: the last frame's sun and cascades are finite numbers. A light direction or a
// cascade of NaN or infinity puts every pixel in shadow (or none), which no NaN in the image shows.
void checkShadowInputs(const Chapter& c) {
    auto finite = [](const glm::mat4& m) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (!std::isfinite(m[i][j])) return false;
        return true;
    };
    if (c.lightControls.sun >= 0) {
        glm::vec3 d = c.scene.lights[size_t(c.lightControls.sun)].direction;
        float length = glm::length(d);
        if (!std::isfinite(length) || !(length > 0.0f))
            throw common::Failure("--check-output: the sun's direction is not finite and non-zero");
    }
    for (size_t i = 0; i < c.cascades.size(); ++i) {
        const Cascade& cascade = c.cascades[i];
        if (!finite(cascade.viewProjection) || !std::isfinite(cascade.texel) || !(cascade.texel > 0.0f) ||
            !std::isfinite(cascade.splitFar) || !(cascade.splitFar > cascade.splitNear))
            throw common::Failure("--check-output: cascade " + std::to_string(i) +
                                  " is not finite (its matrix, texel or slice)");
    }
    std::printf("chapter-17: output check: the sun and %zu cascades finite\n", c.cascades.size());
}

// After the last frame: where the camera and lights went, --benchmark's report, --check-output.
void report(Chapter& c, const common::Options& options) {
    const common::CameraDesc& start = c.scene.camera;
    if (c.camera.position != start.position || c.camera.yaw != start.yaw || c.camera.pitch != start.pitch)
        std::printf("chapter-17: camera moved: at (%.2f, %.2f, %.2f), yaw %.1f, pitch %.1f\n",
                    c.camera.position.x, c.camera.position.y, c.camera.position.z, c.camera.yaw,
                    c.camera.pitch);
    std::vector<std::pair<std::string, std::string>> info =
        common::benchmarkInfo(kChapter, options, c.device, c.target, c.scenePass.formats.depth);
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(kBookGBuffer.formats))});
    common::addPipelineInfo(info, c.scenePass.pipelines.pipelines.size(), c.passesMs);
    info.push_back({"light_pipeline", describeLightKinds(c.lightPass.kinds)});
    info.push_back({"skinning", describeSkinning(c)});
    // Without depth clamping the cascades reach toward the sun as far as the scene does.
    info.push_back({"depth_clamp", c.device.depthClamp ? "yes" : "no: cascades reach the scene's casters"});
    for (const auto& [key, value] : describeCascades(c)) info.push_back({key, value});
    // The bound of the first frame's fragments that setUp checked (common/scene/frame_cost.hpp).
    std::string bound;
    for (uint64_t fragments : c.firstFrameCost)
        bound += (bound.empty() ? "" : ", ") + std::to_string(fragments);
    info.push_back({"first_frame_fragments_bound", bound + " (the view, then each cascade)"});
    common::reportRun(c.run, c.device, info);
    // How often each cascade was drawn (anything: whole, bands, moving casters), and drawn whole:
    // once for a still camera, more as it moves; then what a frame drew of each, on average.
    const ShadowCache& cache = c.shadowPass.cache;
    std::string drawn, whole, texels, draws, moving;
    double frames = double(std::max<uint64_t>(cache.frames, 1));
    auto append = [](std::string& list, const char* format, double value) {
        char text[64];
        std::snprintf(text, sizeof(text), format, value);
        if (!list.empty()) list += ", ";
        list += text;
    };
    for (uint32_t i = 0; i < c.cascadeSettings.count; ++i) {
        append(drawn, "%.0f", double(cache.redraws[i]));
        append(whole, "%.0f", double(cache.wholeRedraws[i]));
        append(texels, "%.0f", double(cache.texels[i]) / frames);
        append(draws, "%.1f", double(cache.draws[i]) / frames);
        append(moving, "%.0f", double(cache.movingFrames[i]));
    }
    std::printf("chapter-17: cascades drawn %s times in %llu frames (whole %s)\n", drawn.c_str(),
                static_cast<unsigned long long>(cache.frames), whole.c_str());
    std::printf("chapter-17: a frame drew %s texels and %s draws per cascade; %llu draws culled\n",
                texels.c_str(), draws.c_str(), static_cast<unsigned long long>(cache.culled));
    uint64_t movingAny = 0;
    for (uint64_t count : cache.movingFrames) movingAny += count;
    if (movingAny > 0) std::printf("chapter-17: moving casters drawn apart in %s frames\n", moving.c_str());
    if (c.farSteps[0] + c.farSteps[1] > 0)
        std::printf("chapter-17: the fitted far plane stepped up %u and down %u times\n", c.farSteps[0],
                    c.farSteps[1]);
    if (c.gui.enabled)
        std::printf("chapter-17: GUI buffers grew %u times, to %zu vertices and %zu indices\n",
                    c.guiPass.growths, c.guiPass.largestVertices, c.guiPass.largestIndices);
    if (c.lightControls.moved) {
        glm::vec3 p = c.lightControls.point >= 0 ? c.scene.lights[size_t(c.lightControls.point)].position
                                                 : glm::vec3(0.0f);
        std::printf("chapter-17: lights moved: sun at %.1f degrees, point light at (%.2f, %.2f, %.2f)\n",
                    c.lightControls.sunAngle, p.x, p.y, p.z);
    }
    std::printf("chapter-17: skinning: %s\n", describeSkinning(c).c_str());
    if (options.switches.count("check-output")) {
        checkLightOutput(c.device, c.lightPass);
        checkShadowInputs(c);
    }
    if (options.switches.count("check-skinning")) checkSkinning(c.device, c.skinningPass, c.gpuScene);
}

//> teardown
void tearDown(Chapter& c) {
    common::destroyRunControl(c.device, c.run);
    destroyPasses(c);
    common::destroyGui(c.gui);
    common::savePipelineCache(c.device, c.pipelineCache);
    common::destroyPipelineCache(c.device, c.pipelineCache);
    common::destroyGpuScene(c.device, c.gpuScene);
    common::destroyFrameSync(c.device, c.frames);
    common::destroyTargetImages(c.target, c.device);
    common::destroyDevice(c.device);
    common::destroyTargetSurface(c.target, c.instance);
    common::destroyInstance(c.instance);
    common::closeTarget(c.target);
}
//< teardown

//> run
void run(const common::Options& options) {
    Chapter chapter;
    setUp(chapter, options);
    frameLoop(chapter, options);
    report(chapter, options);
    tearDown(chapter);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
