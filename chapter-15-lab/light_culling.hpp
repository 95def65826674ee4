// chapter-15-lab: light ranges and tiled light culling (--light-cutoff, --light-culling tiled).
//
// chapter-15's light pass, the book's, shades every pixel with every light, so a frame costs pixels x lights.
// With a range, a point light reaches only so far (pbr.glsl's rangeWindow takes its falloff to
// zero there), and a pixel need only be shaded by the lights that reach it. Tiled culling finds
// them on the GPU each frame, per 8x8-pixel tile, in four compute passes:
//   bounds (light_cull_bounds.comp): each tile's box of surface positions, from the G-buffer;
//   count (light_cull.comp): each light with a range adds 1 to every tile of its screen rectangle
//     whose box its sphere reaches -- work proportional to the tiles a light covers; one
//     invocation per light, one group per light for the few whose rectangle is large;
//   scan (light_cull_scan.comp): counts to list offsets, exactly sized;
//   fill (light_cull.comp again): each light writes its index into those tiles' lists (again per
//     light, then per large light).
// The light pass (both forms, light_tiles.glsl) then loops over the unbounded lights and its
// tile's list.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "chapter-15/gbuffer_layout.hpp"
#include "chapter-15/gpu_types.hpp"
#include "common/app/cli.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

struct LightPass;

// The culling passes' view of the frame, a scalar-layout uniform buffer per frame in flight, 104
// bytes: the twin of shaders/chapter-15-lab/cull_view.glsl (the layout test checks both agree).
inline constexpr uint32_t kLightTileSize = 8;           // LIGHT_TILE_SIZE
inline constexpr uint32_t kTileOverflow = 0xffffffffu;  // TILE_OVERFLOW
struct CullView {
    glm::mat4 viewRotation;     // camera-relative world space to view space
    glm::vec2 projectionScale;  // the projection's [0][0] and [1][1]
    float near;                 // the near plane
    float margin;               // how far a stored surface position may lie from its pixel's ray
    glm::uvec2 tileCount;       // tiles across and down
    glm::uvec2 extent;          // the G-buffer's size in pixels
    uint32_t capacity;          // light indices the tile lists can hold
    uint32_t unboundedLights;   // the first lights (no range): shaded everywhere, never listed
};
static_assert(sizeof(CullView) == 104 && offsetof(CullView, projectionScale) == 64 &&
              offsetof(CullView, near) == 72 && offsetof(CullView, margin) == 76 &&
              offsetof(CullView, tileCount) == 80 && offsetof(CullView, extent) == 88 &&
              offsetof(CullView, capacity) == 96 && offsetof(CullView, unboundedLights) == 100);

enum class LightCulling { None, Tiled };

// The lab's options that change the lights or the camera.
struct LightOptions {
    LightCulling culling = LightCulling::None;  // --light-culling
    float orbitDegrees = 0.0f;                  // --orbit: the camera's yaw turns this much a frame
};
// Reads --light-culling, --orbit and --light-cutoff (applied to the scene's lights here, with a
// line saying so). A bad number is an InputError naming the option.
LightOptions readLightOptions(const common::Options& options, common::Scene& scene);
// Point lights with a range: those tiled culling lists per tile.
uint32_t boundedLightCount(const common::Scene& scene);

// --light-cutoff E: every point light without a range gets the distance at which its irradiance,
// intensity x brightest colour channel / d^2, falls to E. Returns how many lights got one.
size_t applyLightCutoff(common::Scene& scene, float cutoff);

// Tiled culling's order of the lights: those without a range (directional lights, point lights
// without one: every pixel's) first, then those with one, each group in scene order. Returns how
// many come first.
uint32_t putUnboundedFirst(std::vector<ShaderLight>& lights);

// What each frame in flight owns: its CullView and the descriptor set that binds it with the
// shared buffers (set 3 of the culling passes, TILE_SET of the light pass).
struct LightCullingFrame {
    common::Buffer view;  // CullView, host-visible
    VkDescriptorSet set = VK_NULL_HANDLE;
};

struct LightCullingPass {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<LightCullingFrame> frames;
    // One of each, rebuilt every frame; barriers order one frame's use after the previous one's.
    common::Buffer tileBounds;  // 2 vec4 per tile
    common::Buffer tileCounts;  // uint per tile
    common::Buffer tileLists;   // uvec2 per tile
    common::Buffer indices;     // `capacity` uints
    common::Buffer stats;       // CullStats, host-visible: read after the run
    common::Buffer large;       // the large lights and their indirect dispatch
    VkExtent2D extent{};
    glm::uvec2 tiles{0};
    uint32_t capacity = 0;
    uint32_t boundedLights = 0;  // lights with a range
    float margin = 0.0f;         // CullView::margin, from the G-buffer layout and the scene's size
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    std::string boundsShader;  // the bounds pipeline's shader (the G-buffer layout's variant)
    VkPipeline bounds = VK_NULL_HANDLE, count = VK_NULL_HANDLE, countLarge = VK_NULL_HANDLE,
               scan = VK_NULL_HANDLE, fill = VK_NULL_HANDLE, fillLarge = VK_NULL_HANDLE;
};

// The set layout, buffers and per-frame sets (before the light pass, whose pipelines bind the set).
LightCullingPass createLightCulling(const common::Device& device, VkExtent2D extent, uint32_t framesInFlight,
                                    uint32_t boundedLights, const GBufferLayout& layout, glm::vec3 boundsMin,
                                    glm::vec3 boundsMax);
// The four pipelines, on the light pass's sets 0-2 (G-buffer, lights, scene info); `boundsShader`
// reads the G-buffer's layout.
void createLightCullingPipelines(const common::Device& device, VkPipelineCache cache,
                                 LightCullingPass& culling, const LightPass& lightPass,
                                 const std::string& boundsShader);
// The tile grid and lists follow the window.
// Live reload: new pipelines into `swap` where the reload changed their shaders.
void remakeLightCullingPipelines(const common::Device& device, VkPipelineCache cache, LightCullingPass& c,
                                 const common::ShaderReload& reload, common::PipelineSwap& swap);
void resizeLightCulling(const common::Device& device, LightCullingPass& culling, VkExtent2D extent);
// This frame's camera: view matrix without its translation, projection, near plane; and how many
// lights come first without a range (putUnboundedFirst).
void updateLightCulling(LightCullingPass& culling, uint32_t frame, const glm::mat4& viewRotation,
                        const glm::mat4& projection, float near, uint32_t unboundedLights);
void recordLightCulling(VkCommandBuffer cmd, const LightCullingPass& culling, const LightPass& lightPass,
                        uint32_t frame, const LightView& view);

struct LightCullingStats {
    uint32_t pairs = 0, maxTileLights = 0, overflowTiles = 0, litTiles = 0;
};
// The last frame's statistics (call after the device is idle), and one line of them on stdout.
LightCullingStats readLightCullingStats(const LightCullingPass& culling);
void reportLightCulling(const LightCullingPass& culling);
void destroyLightCulling(const common::Device& device, LightCullingPass& culling);
