// chapter-20's Render: chapter-19's (chapter-19/render.hpp), split between two threads. The main
// thread writes a frame's slot -- its uniforms (the camera, the lights, the cascades), its palette
// (the animation clock's pose), its GlobalBuffers (the instances and draw commands) and its
// FrameSnapshot below -- while the render thread records the frame before it from that frame's
// slot alone (frame_threads.hpp). The same passes, in the same order, the same picture.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "chapter-16/cascades.hpp"
#include "chapter-16/shadow_controls.hpp"
#include "chapter-16/shadow_pass.hpp"
#include "chapter-17/skinning_pass.hpp"
#include "chapter-19/global_buffers.hpp"
#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"

//> snapshot
// What the render thread records a frame from, besides the frame's buffers: written by the main
// thread's update of the frame's slot, read by the render thread while it records that frame, and
// written again only once the frame's fence has signalled (frame_threads.cpp). Values, no
// references: nothing here changes while the frame is recorded.
struct FrameSnapshot {
    glm::vec3 cameraPosition{0.0f};  // the scene pass's
    LightView lightView;             // the view shown, the scene's bounds: the light pass's push
    bool fxaa = false;
    ShadowPlan shadowPlan;  // what the shadow pass draws; the slot's GlobalBuffers point into it
};
//< snapshot

struct Render {
    common::GpuScene gpuScene;
    ScenePass scenePass;
    SkinningPass skinningPass;
    GlobalBuffers globalBuffers;           // the book's: what the indirect draws read, per frame in flight
    std::vector<FrameSnapshot> snapshots;  // per frame in flight: what recording reads of the update
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
// The main thread: frame slot `slot`'s buffers and snapshot, once the slot's fence has signalled.
// `waitForRender` is called first when the update must change what the render thread uses (the
// moving casters' map, made the first time a caster moves).
void updateRender(common::RenderContext& context, Render& render, uint32_t slot, const FrameView& view,
                  const std::function<void()>& waitForRender);
// The render thread: the frame's passes, from its slot (`frame.slot`) and the objects that stay.
void recordRender(common::RenderContext& context, Render& render, common::FrameCommands& frame);
void destroyRender(common::RenderContext& context, Render& render);
