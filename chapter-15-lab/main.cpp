// chapter-15-lab: the study program built on chapter-15's passes, for what goes beyond the book.
// With no option it renders what chapter-15 renders; the options change one thing each, to be
// measured against the book's renderer (render.hpp lists the studies, a file each). As the
// chapters from 15 on, this file is the program's Main (the scene, the keys, the overlay) and
// render.cpp its Render, on the common frame loop (common/app/frame_loop.hpp); --orbit turns the
// camera for benchmarks that move, and the overlay (--gui) switches the G-buffer layout and the
// light pass's form live.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "chapter-15/light_pass.hpp"
#include "chapter-16/shadow_controls.hpp"
#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/core/check.hpp"
#include "common/model/load_model.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/frame_cost.hpp"
#include "common/scene/scene.hpp"
#include "output_dump.hpp"
#include "render.hpp"
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
      {"none", "vsm", "pcf2", "pcf3", "pcf5", "vsm16", "depth"},
      "the sun's shadow from chapter-16's cascades, for the shadow study: none (chapter-15's light); "
      "the book's variance map; the depth compared by the sampler, filtered over 2x2, 3x3 or 5x5 texels; "
      "the variance map in half floats; the depth alone, one texel compared in the shader"},
     {"shadow-layers",
      {"geometry", "multiview", "passes"},
      "how --shadows draws the cascades: one pass with the book's geometry shader; one pass with "
      "multiview (a view per cascade); one pass per cascade"},
     {"cascades", cascadesChoice().values, "with --shadows: cascades of the sun's shadow map"},
     {"shadow-map-size", shadowMapSizeChoice().values,
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

// The lab's Main: the scene and what the keys and the overlay change; the Vulkan objects every
// chapter makes (common::RenderContext) and the lab's Render (render.hpp).
struct Lab {
    common::Scene scene;
    common::RenderContext context;
    Render render;
    RendererChoice renderer;  // what the overlay asks for (render.active: what the passes were made for)
    common::Camera camera;
    common::CameraInput cameraInput;
    common::LightControls lightControls;
    LightView lightView;
    bool fxaa = false;
    common::KeyPress viewKey{GLFW_KEY_V}, fxaaKey{GLFW_KEY_F};
};

FrameView frameView(Lab& c) {
    return {c.camera, c.scene, c.lightControls.sun, c.lightView, c.fxaa};
}

//> overlay
// The overlay (--gui): chapter-15's, with the G-buffer layout and the light pass's form in the
// timings window (switched at the next frame).
void overlayWidgets(Lab& c) {
    bool deferred = !c.render.studies.forward, switchable = !c.render.studies.study.enabled;
    // "visibility" (the last view) only with --shadows, where the overlay has no renderer switch.
    std::vector<std::string> views = kChapter.views;
    if (switchable) views.pop_back();
    common::guiTimingsWindow(
        c.context.gui, c.context.run, deferred ? views : std::vector<std::string>{"final"}, &c.lightView.view,
        {"V  cycles the views", "F  toggles FXAA", common::kLightKeysHelp[0], common::kLightKeysHelp[1]});
    ImGui::Begin("Frame");  // appends to the timings window
    ImGui::Checkbox("FXAA (F)", &c.fxaa);
    if (deferred && switchable) {  // --shading forward has neither; the shadow study, one
        common::guiCombo("G-buffer", labLayoutNames(), &c.renderer.layout);
        common::guiCombo("light pass", {"fragment", "compute"}, &c.renderer.lightPass);
    }
    ImGui::End();

    common::beginLightsWindow(c.lightControls, c.scene, c.render.gpuScene);
    common::endLightsWindow();
}
//< overlay

// The keys (unless the overlay has them): the camera, the lights; V cycles the views (none with
// forward shading), F toggles FXAA.
void handleInput(Lab& c, GLFWwindow* window, float seconds, bool keys, bool mouse) {
    float sceneSize = glm::length(c.render.gpuScene.boundsMax - c.render.gpuScene.boundsMin);
    common::moveCamera(window, c.camera, c.cameraInput, seconds, sceneSize * 0.15f, keys, mouse);
    if (keys)
        common::moveLights(window, c.lightControls, c.scene, c.render.gpuScene, seconds, sceneSize * 0.05f);
    if (common::pressedOnce(window, c.viewKey) && keys && !c.render.studies.forward)
        c.lightView.view =
            (c.lightView.view + 1) % int(kChapter.views.size() - (c.render.studies.study.enabled ? 0 : 1));
    if (common::pressedOnce(window, c.fxaaKey) && keys) c.fxaa = !c.fxaa;
}

//> setup
void setUp(Lab& c, const common::Options& options) {
    common::ModelCache models;
    c.scene = common::sceneFromOptions(options, models);
    // Light ranges from --light-cutoff, tiled culling, the camera turning, the shadow study.
    LabStudies studies = readLabStudies(options, c.scene);
    // chapter-15's features; the shadow study's: chapter-16's geometry shader and depth clamping,
    // or multiview.
    const ShadowStudyOptions& study = studies.study;
    c.context = common::openRenderContext(
        options, "chapter-15-lab", "chapter-15-lab",
        {.dynamicRendering = true,
         .synchronization2 = true,
         .scalarBlockLayout = true,
         .geometryShader = study.enabled && study.layers == ShadowLayers::GeometryShader,
         .depthClampWhereAvailable = study.enabled,
         .multiview = study.enabled && study.layers == ShadowLayers::Multiview});
    // What the first frame's view may cost to rasterise, refused beyond a budget
    // (common/scene/frame_cost.hpp).
    const common::RasterView firstView =
        common::sceneRasterView(c.scene, c.context.target.extent.width, c.context.target.extent.height);
    common::checkFrameCost(c.scene, models, {&firstView, 1});
    c.render = createRender(c.context, c.scene, models, options, studies);
    c.renderer = c.render.active;
    common::startRunControl(c.context, options, renderPassNames(c.render));

    c.camera = {c.scene.camera.position, c.scene.camera.yaw, c.scene.camera.pitch};
    c.lightControls = common::findControlledLights(c.scene);
    c.lightView = {.boundsMin = glm::vec4(c.render.gpuScene.boundsMin, 0.0f),
                   .boundsMax = glm::vec4(c.render.gpuScene.boundsMax, 0.0f),
                   .view = int(options.view),
                   .reversedZ = c.render.layout->layout.reversedZ ? 1 : 0};
    c.fxaa = options.switches.count("fxaa") != 0;
}
//< setup

// After the last frame: where the camera and lights went, --benchmark's report, the tile lists'
// statistics, --check-output, --dump.
void report(Lab& c, const common::Options& options) {
    std::vector<std::pair<std::string, std::string>> info = common::benchmarkInfo(
        kChapter, options, c.context.device, c.context.target, c.render.scenePass.formats.depth);
    addRenderInfo(info, c.render);
    common::reportChapterRun(kChapter, c.context, info, c.scene, c.camera, c.lightControls);
    if (c.render.studies.tiled) reportLightCulling(c.render.culling);
    // The output read back: chapter-15's check, and the PFM files of output_dump.cpp.
    if (options.switches.count("check-output")) checkLightOutput(c.context.device, c.render.light.pass);
    if (options.values.count("dump"))
        dumpFrame(c.context.device, c.render.light.pass, c.render.scenePass, c.lightView,
                  options.values.at("dump"), !c.render.studies.forward);
}

void run(const common::Options& options) {
    if (skinningStudyRequested(options)) return runSkinningStudy(options);  // no scene, no window
    if (options.choices.count("skinning-study-size"))
        throw common::InputError("--skinning-study-size needs --skinning-study");
    Lab c;
    setUp(c, options);
    bool acquireLate = options.choices.count("acquire") != 0 && options.choices.at("acquire") == 1;
    common::runFrameLoop(
        c.context,
        {.remakePipelines =
             [&](const common::ShaderReload& reload, common::PipelineSwap& swap) {
                 remakeRenderPipelines(c.context, c.render, reload, swap);
             },
         .overlay =
             [&] {
                 overlayWidgets(c);
                 if (c.renderer.layout != c.render.active.layout ||
                     c.renderer.lightPass != c.render.active.lightPass)
                     switchRenderer(c.context, c.render, c.renderer, c.scene, c.lightView);
             },
         .input = [&](GLFWwindow* window, float seconds, bool keys,
                      bool mouse) { handleInput(c, window, seconds, keys, mouse); },
         .update =
             [&](uint32_t, uint32_t slot) {
                 c.camera.yaw += c.render.studies.lights.orbitDegrees;  // --orbit: 0 unless asked
                 updateRender(c.context, c.render, slot, frameView(c));
             },
         .record =
             [&](common::FrameCommands& frame) { recordRender(c.context, c.render, frame, frameView(c)); },
         .present =
             [&](common::FrameCommands& frame) { recordPresent(c.context, c.render, frame, frameView(c)); },
         .acquireLate = acquireLate,
         .resize = [&] { resizeRender(c.context, c.render); }});
    report(c, options);
    destroyRender(c.context, c.render);
    common::closeRenderContext(c.context);
}

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, kChapter, run);
}
