// chapter-15-lab's Render: chapter-15's (chapter-15/render.hpp) with a branch wherever a study
// changes it. Each study is a file of its own, in the chapters' shape (its pass created, resized,
// reloaded, updated, recorded, destroyed):
//   gbuffer_layouts.cpp     --gbuffer: the G-buffer in other layouts (the overlay switches it live);
//   compute_light_pass.cpp  --light-pass compute: the light pass as a compute dispatch;
//   light_culling.cpp       --light-cutoff, --light-culling tiled: light ranges and tiled culling;
//   forward_shading.cpp     --shading forward: no G-buffer, every fragment lit as it is drawn;
//   shadow_study.cpp        --shadows: chapter-16's cascades drawn and filtered in other ways;
//   output_dump.cpp         --dump: the last frame as PFM files for the accuracy tools;
//   skinning_study.cpp      --skinning-study: chapter-17's skinning in other forms (no frame loop).
// The passes in the order a frame records them: shadow (--shadows), scene, cull (tiled), light,
// then post; forward shading records a forward pass and post.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "compute_light_pass.hpp"
#include "forward_shading.hpp"
#include "gbuffer_layouts.hpp"
#include "light_culling.hpp"
#include "shadow_study.hpp"

// What the studies ask for, read from the options once.
struct LabStudies {
    LightOptions lights;       // --light-cutoff (applied to the scene), --light-culling, --orbit
    bool forward = false;      // --shading forward
    bool tiled = false;        // --light-culling tiled
    ShadowStudyOptions study;  // --shadows
    bool generic = false;      // --pipelines generic
};
LabStudies readLabStudies(const common::Options& options, common::Scene& scene);

// The G-buffer layout and the light pass's form (the overlay switches them at the next frame).
struct RendererChoice {
    int layout = 0;     // index into labLayouts()
    int lightPass = 0;  // LightPassKind
};

// The light pass for a layout and form, with the compute form's pipeline.
struct LightPasses {
    LightPass pass;
    ComputeLightPass compute;  // --light-pass compute
};

struct Render {
    common::GpuScene gpuScene;
    LabStudies studies;
    RendererChoice active;  // what the passes were made for
    const LabLayout* layout = nullptr;
    LightPassKind lightKind = LightPassKind::Fragment;
    ScenePass scenePass;       // the layout's G-buffer, or (forward) depth alone
    ShadowStudy shadowStudy;   // --shadows
    LightCullingPass culling;  // --light-culling tiled
    LightPasses light;
    ForwardPass forwardPass;  // --shading forward
    common::PostPass postPass;
    double passesMs = 0.0;  // how long the passes took to make at start-up (pipelines, mostly)
};

// What a frame draws that the lab's Main changes: the camera, the lights (`sun`: the one the
// shadow study's cascades follow, -1 for none), the view shown (updateRender fills in its
// projection), FXAA.
struct FrameView {
    const common::Camera& camera;
    const common::Scene& scene;
    int sun = -1;
    LightView& lightView;
    bool fxaa = false;
};

// `models` may be cleared after: the passes keep nothing of it.
Render createRender(common::RenderContext& context, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options, const LabStudies& studies);
std::vector<std::string> renderPassNames(const Render& render);
// chapter-16's cascades for a frame's camera and sun, as the shadow study draws them (none
// without a sun).
std::vector<Cascade> studyCascades(const Render& render, const common::Device& device, VkExtent2D extent,
                                   const common::Scene& scene, const glm::mat4& view, int sun);
// From the overlay: another G-buffer layout or light-pass form. Every pass that depends on them is
// made again (the G-buffer with the scene pass); the scene, the window and the run go on.
void switchRenderer(common::RenderContext& context, Render& render, const RendererChoice& choice,
                    const common::Scene& scene, LightView& lightView);
void resizeRender(common::RenderContext& context, Render& render);
void remakeRenderPipelines(common::RenderContext& context, Render& render, const common::ShaderReload& reload,
                           common::PipelineSwap& swap);
void updateRender(common::RenderContext& context, Render& render, uint32_t slot, const FrameView& view);
// The passes before the presented image (`recordRender`), and the post pass that writes it.
void recordRender(common::RenderContext& context, Render& render, common::FrameCommands& frame,
                  const FrameView& view);
void recordPresent(common::RenderContext& context, Render& render, common::FrameCommands& frame,
                   const FrameView& view);
// --benchmark's rows for what the studies changed.
void addRenderInfo(std::vector<std::pair<std::string, std::string>>& info, const Render& render);
void destroyRender(common::RenderContext& context, Render& render);
