// chapter-15: deferred rendering II, PBR -- the book's chapter 15 in C++.
//
// chapter-14's frame with a full PBR G-buffer and real lighting. As the book's chapter splits its
// program, this file is its Main (the scene, the keys, the overlay's controls) and render.cpp its
// Render (the passes: the scene pass into the G-buffer, the light pass, the post pass). From this
// chapter on, the frame loop that chapters 06 to 14 write out is common/app/frame_loop.cpp's: it
// calls the steps that run() at the end of this file gives it.
#include <vulkan/vulkan.h>

#include <cstdio>
#include <string>
#include <vector>

#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/scene.hpp"
#include "gbuffer_layout.hpp"
#include "render.hpp"

namespace {

const common::ChapterInfo kChapter{
    "chapter-15",
    "deferred rendering II: PBR G-buffer, normal maps, lights (the book's chapter 15)",
    {"final", "position", "albedo", "normal", "pbr", "depth"},  // the order of shade_pixel.glsl's `view`
    {{"fxaa", "anti-alias the final image with FXAA (F toggles it in the window)"},
     {"check-output", "read the light output back as floats; fail on NaN, infinity or a negative value"},
     common::kGuiSwitch,
     common::kGuiStillSwitch},
    {common::kGuiClickChoice, common::kGuiScaleChoice, common::kPipelinesChoice},
};

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
};
//< chapter-state

FrameView frameView(const Chapter& c) {
    return {c.camera, c.scene, c.lightView, c.fxaa};
}

//> overlay
// The overlay (--gui): the timings window with the view selector (common/app/gui.cpp) and FXAA; a
// second window with the book's light controls and the ambient light.
void overlayWidgets(Chapter& c) {
    common::guiTimingsWindow(
        c.context.gui, c.context.run, kChapter.views, &c.lightView.view,
        {"V  cycles the views", "F  toggles FXAA", common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", &c.fxaa);
    ImGui::End();

    common::beginLightsWindow(c.lightControls, c.scene, c.render.gpuScene);
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

//> setup
void setUp(Chapter& c, const common::Options& options) {
    common::ModelCache models;
    c.scene = common::sceneFromOptions(options, models);
    // scalarBlockLayout: the feature this chapter adds -- the lights and the scene info are read
    // with the C-like scalar layout (gpu_types.hpp).
    c.context = common::openRenderContext(
        options, "chapter-15", "chapter-15: deferred rendering II, PBR",
        {.dynamicRendering = true, .synchronization2 = true, .scalarBlockLayout = true});
    // What the first frame may cost to rasterise, refused beyond a budget (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(c.scene, c.context.target.extent.width, c.context.target.extent.height);
    common::checkFrameCost(c.scene, models, {&firstView, 1});
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
}
//< setup

// After the last frame: where the camera and lights went, --benchmark's report, --check-output.
void report(Chapter& c, const common::Options& options) {
    std::vector<std::pair<std::string, std::string>> info = common::benchmarkInfo(
        kChapter, options, c.context.device, c.context.target, c.render.scenePass.formats.depth);
    info.push_back({"gbuffer_bytes_per_pixel", std::to_string(common::bytesPerPixel(kBookGBuffer.formats))});
    common::addPipelineInfo(info, c.render.scenePass.pipelines.pipelines.size(), c.render.passesMs);
    info.push_back({"light_pipeline", describeLightKinds(c.render.lightPass.kinds)});
    common::reportChapterRun(kChapter, c.context, info, c.scene, c.camera, c.lightControls);
    if (options.switches.count("check-output")) checkLightOutput(c.context.device, c.render.lightPass);
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
         .update = [&](uint32_t, uint32_t slot) { updateRender(c.context, c.render, slot, frameView(c)); },
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
