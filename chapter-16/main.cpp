// chapter-16: cascade shadows -- the book's chapter 16 in C++.
//
// chapter-15's frame with the directional light's shadow, from a shadow map in cascades. As in
// chapter-15, this file is the book's Main (the scene, the keys, the overlay's controls) and
// render.cpp its Render; what this chapter changes in them: the shadow pass before the scene pass
// and the cascades each frame (render.cpp), the shadow controls in the overlay and the book's
// scene with its tree (below). The shadow options, the report's cascade rows and --check-output's
// test of the cascades are in shadow_controls.cpp, shared with chapter-17.
#include <vulkan/vulkan.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "chapter-15/gbuffer_layout.hpp"
#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/test_motion.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/scene.hpp"
#include "render.hpp"
#include "shadow_controls.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-16",
    "cascade shadows: the sun's shadow map in cascades over chapter-15's renderer (the book's chapter 16)",
    // The order of shade_pixel.glsl's `view`, then light.frag's own.
    {"final", "position", "albedo", "normal", "pbr", "depth", "shadow-map", "cascades", "visibility"},
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {common::kGuiClickChoice, common::kGuiScaleChoice, common::kPipelinesChoice, cascadesChoice(),
     shadowMapSizeChoice(), shadowFarChoice(), shadowRedrawChoice(), common::kCameraMotionChoice,
     common::kLightMotionChoice},
};
constexpr int kCascadesView = 7;  // kChapter.views' "cascades": the book's cascade debug view

//> chapter-state
// The book's Main: the scene and what the keys and the overlay change; the Vulkan objects every
// chapter makes (common::RenderContext) and this chapter's Render (render.hpp).
struct Chapter {
    common::Scene scene;
    common::RenderContext context;
    Render render;
    // What the frames change.
    common::Camera camera;
    common::CameraInput cameraInput;
    common::LightControls lightControls;
    LightView lightView;
    bool fxaa = false;
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
    common::TestMotion testMotion;         // --camera-motion, --light-motion
    std::vector<uint64_t> firstFrameCost;  // fragments bound: the view, then each cascade
};
//< chapter-state

FrameView frameView(const Chapter& c) {
    return {c.camera, c.scene, c.lightControls.sun, c.lightView, c.fxaa};
}

//> overlay
// The overlay (--gui): the timings window with the view selector (common/app/gui.cpp) and FXAA; a
// second window with chapter-15's light controls, the ambient light and the shadow controls.
void overlayWidgets(Chapter& c) {
    common::guiTimingsWindow(
        c.context.gui, c.context.run, kChapter.views, &c.lightView.view,
        {"V  cycles the views", "F  toggles FXAA", common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", &c.fxaa);
    ImGui::End();

    common::beginLightsWindow(c.lightControls, c.scene, c.render.gpuScene);
    shadowWidgets(&c.lightView.view, kCascadesView, c.render.shadow, c.render.cascades, c.render.shadowPass);
    common::endLightsWindow();
}
//< overlay

//> input
// The keys (unless the overlay has them): the camera, the lights; V cycles the views, F toggles FXAA.
void handleInput(Chapter& c, GLFWwindow* window, float seconds, bool keys, bool mouse) {
    float sceneSize = glm::length(c.render.gpuScene.boundsMax - c.render.gpuScene.boundsMin);
    common::moveCamera(window, c.camera, c.cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
    if (keys)
        common::moveLights(window, c.lightControls, c.scene, c.render.gpuScene, seconds, sceneSize * 0.05f);
    if (common::pressedOnce(window, c.viewKey) && keys)
        c.lightView.view = (c.lightView.view + 1) % int(kChapter.views.size());
    if (common::pressedOnce(window, c.fxaaKey) && keys) c.fxaa = !c.fxaa;
}
//< input

//> book-scene
// --book-scene: the book's chapter 16 changes chapter 15's scene (its Main.java): the camera at
// (-5, 5, 0), turned 90 degrees about y (looking along +x) and 20 down; zNear 0.5 and zFar 50; the
// sun straight down at intensity 8; no point light, and no marker for it; and a tree at the
// origin, scaled 0.005, which Main.java loads in the book's converted format
// (booksamples/chapter-16/resources/models/tree/tree.json, common/model/book_model.hpp); the clone
// keeps the tree.obj it was converted from beside it, read where the converted files are missing.
void useBookChapter16Scene(common::Scene& scene, const std::filesystem::path& bookScene) {
    scene.camera.position = {-5.0f, 5.0f, 0.0f};
    scene.camera.yaw = 90.0f;
    scene.camera.pitch = -20.0f;
    scene.camera.near = 0.5f;
    scene.camera.far = 50.0f;
    scene.lights = {common::Light{
        .type = common::Light::Type::Directional, .direction = {0.0f, -1.0f, 0.0f}, .intensity = 8.0f}};
    scene.models.resize(1);  // Sponza; the point light's marker goes with the light
    // The clone's chapter-16 sample, from the clone or from chapter-15's Sponza.gltf in it
    // (booksamples/chapter-15/resources/models/sponza/Sponza.gltf), however the path was written.
    std::error_code ec;
    std::filesystem::path given =
        std::filesystem::weakly_canonical(std::filesystem::absolute(bookScene, ec), ec);
    std::filesystem::path samples =
        std::filesystem::is_directory(given, ec)
            ? given / "booksamples"
            : given.parent_path().parent_path().parent_path().parent_path().parent_path();
    std::filesystem::path treeDir = samples / "chapter-16" / "resources" / "models" / "tree";
    // The converted files whole (the JSON and its vertex and index files), else the OBJ.
    std::filesystem::path tree = treeDir / "tree.json";
    for (const char* part : {"tree.json", "tree.vtx", "tree.idx"})
        if (!std::filesystem::is_regular_file(treeDir / part, ec)) tree = treeDir / "tree.obj";
    if (!std::filesystem::is_regular_file(tree, ec)) {
        common::warn("the book's tree is not at " + common::utf8(treeDir / "tree.json") + " (nor tree.obj)" +
                     ": the scene without it");
        return;
    }
    common::ModelInstance treeInstance{.file = tree};
    treeInstance.transform.scale = glm::vec3(0.005f);
    scene.models.push_back(treeInstance);
}
//< book-scene

//> setup
void setUp(Chapter& c, const common::Options& options) {
    common::ModelCache models;
    c.scene = common::sceneFromOptions(options, models);
    if (!options.bookScene.empty()) useBookChapter16Scene(c.scene, options.bookScene);
    // What this chapter adds: geometryShader (the shadow pass sends each triangle to every
    // cascade's layer) and depthClamp where the device has it (casters in front of a cascade's box
    // kept); the rest is chapter-15's.
    c.context = common::openRenderContext(options, "chapter-16", "chapter-16: cascade shadows",
                                          {.dynamicRendering = true,
                                           .synchronization2 = true,
                                           .scalarBlockLayout = true,
                                           .geometryShader = true,
                                           .depthClampWhereAvailable = true});
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
    addShadowInfo(info, c.context.device, c.render.cascades, c.render.shadowPass.cache, c.firstFrameCost);
    common::reportChapterRun(kChapter, c.context, info, c.scene, c.camera, c.lightControls);
    printShadowReport(kChapter.name, c.render.shadowPass.cache, c.render.shadow.settings.count,
                      c.render.farSteps);
    if (options.switches.count("check-output")) {
        checkLightOutput(c.context.device, c.render.lightPass);
        checkShadowInputs(kChapter.name, c.scene, c.lightControls.sun, c.render.cascades);
    }
}

//> run
void run(const common::Options& options) {
    Chapter c;
    setUp(c, options);
    common::runFrameLoop(
        c.context,
        {.remakePipelines =
             [&](const common::ShaderReload& reload, common::PipelineSwap& swap) {
                 remakeRenderPipelines(c.context, c.render, reload, swap);
             },
         .overlay = [&] { overlayWidgets(c); },
         .input = [&](GLFWwindow* window, float seconds, bool keys,
                      bool mouse) { handleInput(c, window, seconds, keys, mouse); },
         .update =
             [&](uint32_t frame, uint32_t slot) {
                 common::moveForTesting(c.testMotion, frame, c.camera, c.lightControls, c.scene,
                                        c.render.gpuScene);
                 updateRender(c.context, c.render, slot, frameView(c));
             },
         .record =
             [&](common::FrameCommands& frame) { recordRender(c.context, c.render, frame, frameView(c)); },
         .resize = [&] { resizeRender(c.context, c.render); }});
    report(c, options);
    destroyRender(c.context, c.render);
    common::closeRenderContext(c.context);
}
//< run

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
