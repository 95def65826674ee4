// chapter-16: the shadow pass -- the scene's depth, seen from the directional light, into one layer
// per cascade of a layered image, in one pass: a geometry shader sends each triangle to every
// cascade (gl_Layer). As the book's ShadowRender, a variance shadow map: each texel holds the
// depth's first two moments (R32G32_SFLOAT), beside a depth buffer of the scene pass's format.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "cascades.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/pipeline.hpp"
#include "shadow_cache.hpp"

inline constexpr VkFormat kMomentsFormat = VK_FORMAT_R32G32_SFLOAT;
// The light shader's specialisation constant MOVING_CASTERS (shadows.glsl): whether it reads the
// moving casters' map.
inline constexpr uint32_t kMovingCastersConstant = 5;

// What the geometry shader and the light pass read about the cascades (std140): each cascade's
// light view-projection, where each cascade's slice ends (view distance), how many there are,
// the camera's view matrix (the light pass picks a cascade by view depth), and where each
// cascade's box starts in its layer (shadow_cache.hpp: the layers are addressed toroidally).
struct CascadeUniform {
    glm::mat4 viewProjection[kMaxCascades];
    glm::vec4 splitFar;   // x, y, z, w: cascades 0..3
    glm::vec4 texelSize;  // a texel's size in the world, per cascade
    glm::mat4 cameraView;
    int32_t count;
    uint32_t moving;  // bit i: the moving casters' map holds casters of cascade i
    int32_t padding[2];
    glm::ivec4 layerOffset[kMaxCascades];  // x, y: the texel where the box's first texel lies
    glm::vec4 toSun;                       // xyz: unit vector toward the sun, world space
    glm::vec4 varianceFloor;               // per cascade: the Chebyshev bound's least variance
};

// The shaders of a shadow pipeline, chapter-16's by default: the model matrix, then the geometry
// shader sending each triangle to every cascade's layer, then the moments. (chapter-15-lab's
// shadow study draws the layers without the geometry stage -- multiview, a pass per cascade --
// and the depth alone, for depth comparison.)
struct ShadowPipelineShaders {
    const char* vertex = "chapter-16/shadow.vert";
    const char* geometry = "chapter-16/shadow.geom";  // nullptr: no geometry stage
    const char* fragment = "chapter-16/shadow.frag";
    bool moments = true;                      // a colour attachment of momentsFormat; false: depth alone
    VkFormat momentsFormat = kMomentsFormat;  // chapter-15-lab's shadow study: also half floats
    uint32_t viewMask = 0;                    // multiview: a bit per cascade
    bool vertexInput =
        true;  // the scene pass's MeshDrawing's: false when the vertex shader pulls (chapter-18)
};
// `alphaTest`: the cut-outs' pipeline (constant_id 0 ALPHA_TEST); `layout` as ShadowPass's.
VkPipeline createShadowPipeline(const common::Device& device, VkPipelineCache cache, VkPipelineLayout layout,
                                VkFormat depthFormat, const ShadowPipelineShaders& shaders, bool alphaTest);
// One of the scene's draws into a shadow map, inside a rendering: with its material's pipeline
// (cut-out or opaque; `bound` the one bound last), its mesh, its textures (set 2) and its model
// matrix and material (push constants); sets 0 and 1 bound by the caller. `firstInstance`
// reaches the vertex shader as gl_InstanceIndex: chapter-16's the layers the geometry shader sends
// the draw to (bit i: cascade i), chapter-15-lab's pass per cascade its cascade.
void recordShadowDraw(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipeline opaque, VkPipeline cutout,
                      VkPipeline& bound, const ScenePass& scenePass, const common::GpuScene& scene,
                      uint32_t draw, uint32_t firstInstance);
// Every draw of the scene so (chapter-15-lab's study, which draws every cascade whole).
void recordShadowDraws(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipeline opaque, VkPipeline cutout,
                       const ScenePass& scenePass, const common::GpuScene& scene, uint32_t firstInstance);

// The shadow pipelines' layout: set 0 `cascades` (the cascade uniform), sets 1 and 2 the scene
// pass's materials and textures, and the scene pass's push constants.
VkPipelineLayout createShadowPipelineLayout(const common::Device& device, VkDescriptorSetLayout cascades,
                                            const ScenePass& scenePass);
// The cascade uniform for `cascades` and the camera's view; each box at its layer's first texel
// and no moving casters' map (shadow_pass.cpp adds them for chapter-16's cache).
CascadeUniform cascadeUniform(const std::vector<Cascade>& cascades, const glm::mat4& cameraView);

struct ShadowPass {
    CascadeSettings settings;
    ShadowPipelineShaders shaders;  // chapter-16's; chapter-17 compiles the same under its name
    common::Image moments;          // R32G32_SFLOAT: depth, depth^2; a layer per cascade
    common::Image depth;            // the scene pass's depth format (D32_SFLOAT, or X8_D24)
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkDescriptorSetLayout cascadesLayout = VK_NULL_HANDLE;  // set 0: the cascades (geometry stage)
    VkDescriptorSetLayout readLayout = VK_NULL_HANDLE;      // the light pass's set: moments + cascades
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::Buffer> cascades;  // CascadeUniform, per frame in flight, host-visible
    std::vector<VkDescriptorSet> cascadesSets;
    std::vector<VkDescriptorSet> readSets;
    VkSampler sampler = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    VkPipeline opaque = VK_NULL_HANDLE;  // constant_id 0 ALPHA_TEST off
    VkPipeline cutout = VK_NULL_HANDLE;
    // What each layer holds and what this frame draws (shadow_cache.hpp): --shadow-redraw.
    ShadowCache cache;
    ShadowPlan plan;
    bool momentsDefined = false;  // the moments hold what an earlier frame drew (else UNDEFINED)
    // The moving casters' map, made the first time a caster moves (--shadow-redraw scrolled), as
    // `moments`; until then the light pass's binding 3 names `moments` (never read).
    common::Image movingMoments;
    bool movingDefined = false;
};

// Throws Failure when the device cannot render to and sample R32G32_SFLOAT; `scenePass` lends its materials
// and textures sets.
ShadowPass createShadowPass(const common::Device& device, VkPipelineCache cache,
                            const CascadeSettings& settings, ShadowRedraw redraw, const ScenePass& scenePass,
                            const common::GpuScene& scene, uint32_t framesInFlight,
                            const ShadowPipelineShaders& shaders = {});
// This frame's cascades into frame slot `frame`'s uniform, and what the shadow pass draws of
// them (planShadows, shadow_cache.hpp) for the scene's draws where they are now. Makes the moving
// casters' map the first time the plan needs it, after waiting for the device: returns true then
// (the light pipeline is to read it from now on: kMovingCastersConstant). `beforeMakingMap`, when
// given, runs first (chapter-20: the render thread is waited for, as it may be recording).
bool updateCascades(const common::Device& device, ShadowPass& pass, uint32_t frame,
                    const std::vector<Cascade>& cascades, const glm::mat4& cameraView,
                    const common::GpuScene& scene, const std::function<void()>& beforeMakingMap = {});
// What records a batch's draws inside the shadow rendering (viewport, scissor and sets 0 and 1 set;
// `bound` the pipeline bound last): one recordShadowDraw each by default; chapter-19 draws them
// indirectly.
using ShadowDrawsRecorder =
    std::function<void(VkCommandBuffer cmd, const std::vector<ShadowDraw>& draws, VkPipeline& bound)>;
void recordShadowPass(VkCommandBuffer cmd, ShadowPass& pass, const ScenePass& scenePass,
                      const common::GpuScene& scene, uint32_t frame, const ShadowDrawsRecorder& draws = {});
// The same for a plan kept apart from the pass (chapter-20: the plan of the frame being recorded,
// while the next frame's is made on another thread).
void recordShadowPass(VkCommandBuffer cmd, ShadowPass& pass, const ShadowPlan& plan,
                      const ScenePass& scenePass, const common::GpuScene& scene, uint32_t frame,
                      const ShadowDrawsRecorder& draws);
void destroyShadowPass(const common::Device& device, ShadowPass& pass);
// Every layer drawn whole next frame (a resize; a change of --shadow-redraw in the overlay).
void invalidateShadowCache(ShadowPass& pass, ShadowRedraw redraw);
// Live reload: new pipelines into `swap` when the reload changed a shadow shader (every cascade is
// then drawn again).
void remakeShadowPipelines(const common::Device& device, VkPipelineCache cache, ShadowPass& pass,
                           const common::ShaderReload& reload, common::PipelineSwap& swap);
