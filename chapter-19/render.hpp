// chapter-19's Render: chapter-18's (chapter-18/render.hpp), its scene and shadow passes drawing
// indirectly: the book's GlobalBuffers (global_buffers.hpp) hold, per frame in flight, the draws'
// matrices, their instances and the draw commands, written by the host each frame; each pass records
// one vkCmdDrawIndexedIndirect per material. The same passes, in the same order, the same picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "chapter-16/cascades.hpp"
#include "chapter-16/shadow_controls.hpp"
#include "chapter-16/shadow_pass.hpp"
#include "chapter-17/skinning_pass.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "global_buffers.hpp"

struct Render {
    common::GpuScene gpuScene;
    ScenePass scenePass;
    SkinningPass skinningPass;
    GlobalBuffers globalBuffers;  // the book's: what the indirect draws read, per frame in flight
    ShadowPass shadowPass;
    LightPass lightPass;
    common::PostPass postPass;
    ShadowOptions shadow;           // the cascades asked for, where the last one ends, what is redrawn
    std::vector<Cascade> cascades;  // this frame's (the book's CascadeShadows)
    uint32_t farSteps[2]{};         // how often the fitted far plane stepped up and down
    double passesMs = 0.0;          // how long the passes took to make at start-up (pipelines, mostly)
};

// What a frame draws that the chapter's Main changes: the camera, the lights (`sun`: the
// directional light that casts the shadows, -1 for none), the animation clock, the view shown, FXAA.
struct FrameView {
    const common::Camera& camera;
    const common::Scene& scene;
    int sun = -1;
    const AnimationClock& clock;
    const LightView& lightView;
    bool fxaa = false;
};

// `models` stays alive with the Render: the skinning pass poses their rigs.
Render createRender(common::RenderContext& context, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options);
std::vector<std::string> renderPassNames(const Render& render);
// The cascades for a frame's camera and sun, over the view from near to where the scene ends
// (--shadow-far scene) or to the far plane; none without a sun.
std::vector<Cascade> frameCascades(Render& render, VkExtent2D extent, const FrameView& view);
void resizeRender(common::RenderContext& context, Render& render);
void remakeRenderPipelines(common::RenderContext& context, Render& render, const common::ShaderReload& reload,
                           common::PipelineSwap& swap);
void updateRender(common::RenderContext& context, Render& render, uint32_t slot, const FrameView& view);
void recordRender(common::RenderContext& context, Render& render, common::FrameCommands& frame,
                  const FrameView& view);
void destroyRender(common::RenderContext& context, Render& render);
