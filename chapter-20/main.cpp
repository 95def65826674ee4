// chapter-20: multi-threading -- the book's chapter 20 in C++.
//
// chapter-19's scene and picture, its frame on two threads: the main thread reads the window, runs
// the input and the update and writes the next frame's slot, while a render thread records,
// submits and presents the frame before it (frame_threads.cpp). This file is chapter-19's Main;
// what it changes: the loop it runs (run), the update's wait for the render thread, and the
// chapter's name.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-16/shadow_controls.hpp"
#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/test_motion.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/scene.hpp"
#include "frame_threads.hpp"
#include "render.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-20",
    "multi-threading: chapter-19's frame recorded, submitted and presented on a thread of its own while the "
    "main thread updates the next (the book's chapter 20)",
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
     cascadesChoice(),
     shadowMapSizeChoice(),
     shadowFarChoice(),
     shadowRedrawChoice(),
     common::kCameraMotionChoice,
     common::kLightMotionChoice},
};
constexpr int kCascadesView = 7;  // kChapter.views' "cascades": the book's cascade debug view

//> chapter-state
// The book's Main: the scene and what the keys and the overlay change; the Vulkan objects every
// chapter makes (common::RenderContext) and this chapter's Render (render.hpp).
struct Chapter {
    common::Scene scene;
    common::ModelCache models;  // the models' CPU data: the skinning pass poses their rigs
    common::RenderContext context;
    Render render;
    // What the frames change.
    common::Camera camera;
    common::CameraInput cameraInput;
    common::LightControls lightControls;
    AnimationClock clock;
    double clockTime = 0.0;  // when the clock last advanced, in seconds since start
    LightView lightView;
    bool fxaa = false;
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F}, playKey{GLFW_KEY_SPACE};
    common::TestMotion testMotion;         // --camera-motion, --light-motion
    std::vector<uint64_t> firstFrameCost;  // fragments bound: the view, then each cascade
};
//< chapter-state

FrameView frameView(const Chapter& c) {
    return {c.camera, c.scene, c.lightControls.sun, c.clock, c.lightView, c.fxaa};
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
void overlayWidgets(Chapter& c) {
    common::guiTimingsWindow(
        c.context.gui, c.context.run, kChapter.views, &c.lightView.view,
        {"V  cycles the views", "F  toggles FXAA", "Space  plays or pauses the animations",
         common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", &c.fxaa);
    ImGui::End();

    common::beginLightsWindow(c.lightControls, c.scene, c.render.gpuScene);
    shadowWidgets(&c.lightView.view, kCascadesView, c.render.shadow, c.render.cascades, c.render.shadowPass);
    animationWidgets(c.clock, c.render.skinningPass);
    common::endLightsWindow();
}
//< overlay

//> input
// The keys (unless the overlay has them): the camera, the lights; V cycles the views, F toggles
// FXAA, Space plays or pauses the animations (the book's Space).
void handleInput(Chapter& c, GLFWwindow* window, float seconds, bool keys, bool mouse) {
    float sceneSize = glm::length(c.render.gpuScene.boundsMax - c.render.gpuScene.boundsMin);
    common::moveCamera(window, c.camera, c.cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
    if (keys)
        common::moveLights(window, c.lightControls, c.scene, c.render.gpuScene, seconds, sceneSize * 0.05f);
    if (common::pressedOnce(window, c.viewKey) && keys)
        c.lightView.view = (c.lightView.view + 1) % int(kChapter.views.size());
    if (common::pressedOnce(window, c.fxaaKey) && keys) c.fxaa = !c.fxaa;
    if (common::pressedOnce(window, c.playKey) && keys) c.clock.playing = !c.clock.playing;
}
//< input

// The animation clock, once a frame: by the wall clock in a window (the book advances a key frame
// per frame, so its speed follows the frame rate), by 1/60 s a frame headless and in benchmarks,
// so that runs repeat exactly.
void advanceClock(Chapter& c, uint32_t frame) {
    double now = common::millisecondsSinceStart() / 1000.0;
    double seconds = c.context.target.window && !c.context.run.benchmark ? now - c.clockTime : 1.0 / 60.0;
    c.clockTime = now;
    if (c.clock.playing && frame > 0) c.clock.seconds += std::min(seconds, 0.25) * double(c.clock.speed);
}

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

// --animation-time SECONDS: a decimal number from 0 to 10^9 (about 32 years), nothing else (strtod
// alone would take 0x10 for 16, and "inf").
double animationTime(const std::string& text) {
    char* end = nullptr;
    double seconds = std::strtod(text.c_str(), &end);
    bool decimal = text.find_first_not_of("0123456789.eE+-") == std::string::npos;
    if (text.empty() || !decimal || end != text.c_str() + text.size() || !std::isfinite(seconds) ||
        seconds < 0.0 || seconds > 1e9)
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
    // chapter-19's features: nothing this chapter does needs more of the device.
    c.context = common::openRenderContext(options, "chapter-20", "chapter-20: multi-threading",
                                          {.dynamicRendering = true,
                                           .synchronization2 = true,
                                           .scalarBlockLayout = true,
                                           .geometryShader = true,
                                           .depthClampWhereAvailable = true,
                                           .bufferDeviceAddress = true,
                                           .indirectDrawing = true});
    c.render = createRender(c.context, c.scene, models, options);
    common::startRunControl(c.context, options, renderPassNames(c.render));

    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.lightControls = common::findControlledLights(c.scene);
    c.lightView = {.boundsMin = glm::vec4(c.render.gpuScene.boundsMin, 0.0f),
                   .boundsMax = glm::vec4(c.render.gpuScene.boundsMax, 0.0f),
                   .view = int(options.view),
                   .near = c.scene.camera.near,
                   .far = c.scene.camera.far};
    c.fxaa = options.switches.count("fxaa") != 0;
    c.testMotion = common::testMotion(options);
    if (auto time = options.values.find("animation-time"); time != options.values.end()) {
        c.clock.seconds = animationTime(time->second);
        c.clock.playing = false;
    }
    c.clockTime = common::millisecondsSinceStart() / 1000.0;

    // What the first frame may cost to rasterise -- the view and every cascade, each triangle
    // drawn into each layer -- refused beyond a budget (common/scene/frame_cost.hpp).
    VkExtent2D extent = c.context.target.extent;
    std::vector<common::RasterView> views{common::sceneRasterView(c.scene, extent.width, extent.height)};
    for (const common::RasterView& cascade :
         cascadeRasterViews(frameCascades(c.render, extent, frameView(c)), c.render.shadow.settings.mapSize))
        views.push_back(cascade);
    c.firstFrameCost = common::checkFrameCost(c.scene, models, views).fragments;
}
//< setup

// After the last frame: where the camera and lights went, --benchmark's report, --check-output.
void report(Chapter& c, const common::Options& options) {
    std::vector<std::pair<std::string, std::string>> info = common::benchmarkInfo(
        kChapter, options, c.context.device, c.context.target, c.render.scenePass.formats.depth);
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(kBookGBuffer.formats))});
    common::addPipelineInfo(info, c.render.scenePass.pipelines.pipelines.size(), c.render.passesMs);
    info.push_back({"light_pipeline", describeLightKinds(c.render.lightPass.kinds)});
    info.push_back({"skinning", describeSkinning(c.render.skinningPass)});
    info.push_back({"indirect", describeGlobalBuffers(c.render.globalBuffers)});
    addShadowInfo(info, c.context.device, c.render.cascades, c.render.shadowPass.cache, c.firstFrameCost);
    common::reportChapterRun(kChapter, c.context, info, c.scene, c.camera, c.lightControls);
    printShadowReport(kChapter.name, c.render.shadowPass.cache, c.render.shadow.settings.count,
                      c.render.farSteps);
    std::printf("chapter-20: skinning: %s\n", describeSkinning(c.render.skinningPass).c_str());
    std::printf("chapter-20: indirect: %s\n", describeGlobalBuffers(c.render.globalBuffers).c_str());
    if (options.switches.count("check-output")) {
        checkLightOutput(c.context.device, c.render.lightPass);
        checkShadowInputs(kChapter.name, c.scene, c.lightControls.sun, c.render.cascades);
    }
    if (options.switches.count("check-skinning"))
        checkSkinning(kChapter.name, c.context.device, c.render.skinningPass, c.render.gpuScene);
}

//> run
// The book's Engine on two threads (frame_threads.hpp): the update on the main thread, the
// recording on the render thread.
void run(const common::Options& options) {
    Chapter c;
    setUp(c, options);
    runThreadedFrameLoop(c.context,
                         {.remakePipelines =
                              [&](const common::ShaderReload& reload, common::PipelineSwap& swap) {
                                  remakeRenderPipelines(c.context, c.render, reload, swap);
                              },
                          .overlay = [&] { overlayWidgets(c); },
                          .resize = [&] { resizeRender(c.context, c.render); },
                          .input = [&](GLFWwindow* window, float seconds, bool keys,
                                       bool mouse) { handleInput(c, window, seconds, keys, mouse); },
                          .advance =
                              [&](uint32_t frame) {
                                  common::moveForTesting(c.testMotion, frame, c.camera, c.lightControls,
                                                         c.scene, c.render.gpuScene);
                                  advanceClock(c, frame);
                              },
                          .update =
                              [&](uint32_t, uint32_t slot, const std::function<void()>& waitForRender) {
                                  updateRender(c.context, c.render, slot, frameView(c), waitForRender);
                              },
                          .record =
                              [&](common::FrameCommands& frame) {
                                  // The test's planted race: the live camera read here, as the book's render
                                  // task does.
                                  if (plantedCameraRace())
                                      c.render.snapshots[frame.slot].cameraPosition = c.camera.position;
                                  recordRender(c.context, c.render, frame);
                              }});
    report(c, options);
    destroyRender(c.context, c.render);
    common::closeRenderContext(c.context);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
