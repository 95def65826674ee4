// chapter-15's Render: what the book's Render.java holds in chapter 15 -- the scene's meshes,
// materials and textures on the GPU (its ModelsCache, MaterialsCache, TextureCache), and its
// passes in the order a frame records them:
//   scene pass (scene_pass.cpp): world position, albedo, normal (normal maps through the TBN
//     matrix) and AO/roughness/metallic into four R16G16B16A16_SFLOAT attachments, plus depth;
//   light pass (light_pass.cpp): Cook-Torrance shading (shaders/include/pbr.glsl) of every pixel
//     by the scene's directional and point lights, from a scalar-layout storage buffer, plus
//     ambient light, into an R32G32B32A32_SFLOAT image;
//   post pass (common/passes/post_pass.cpp): into the presentation image, FXAA optional.
// The GUI pass, the frame's command buffer, its submission and presentation are the frame loop's
// (common/app/frame_loop.hpp), the same for every chapter from 15 on.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/app/cli.hpp"
#include "common/app/frame_loop.hpp"
#include "common/model/load_model.hpp"
#include "common/passes/post_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/scene/scene.hpp"
#include "light_pass.hpp"
#include "scene_pass.hpp"

struct Render {
    common::GpuScene gpuScene;
    ScenePass scenePass;
    LightPass lightPass;
    common::PostPass postPass;
    double passesMs = 0.0;  // how long the passes took to make at start-up (pipelines, mostly)
};

// What a frame draws that the chapter's Main changes: the camera, the lights, the view shown, FXAA.
struct FrameView {
    const common::Camera& camera;
    const common::Scene& scene;
    const LightView& lightView;
    bool fxaa = false;
};

// The scene uploaded and the passes made for it (--pipelines: made for its materials and lights,
// or generic). The names of the passes, in recording order, for startRunControl.
Render createRender(common::RenderContext& context, const common::Scene& scene, common::ModelCache& models,
                    const common::Options& options);
std::vector<std::string> renderPassNames(const Render& render);
// The window changed size: every image of its size, and the post pass for its format.
void resizeRender(common::RenderContext& context, Render& render);
// Edited shaders: the pipelines of the passes that use them (common/app/frame_loop.hpp).
void remakeRenderPipelines(common::RenderContext& context, Render& render, const common::ShaderReload& reload,
                           common::PipelineSwap& swap);
// This frame's uniforms, then its passes.
void updateRender(common::RenderContext& context, Render& render, uint32_t slot, const FrameView& view);
void recordRender(common::RenderContext& context, Render& render, common::FrameCommands& frame,
                  const FrameView& view);
void destroyRender(common::RenderContext& context, Render& render);
