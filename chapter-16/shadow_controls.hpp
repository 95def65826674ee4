// Around chapter-16's shadow pass, what the book's Render does not hold, shared by chapter-17:
// the shadow options (--cascades, --shadow-map-size, --shadow-far, --shadow-redraw) and their
// values, the overlay's shadow controls, the report's rows and lines, and --check-output's test of
// the cascades.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cascades.hpp"
#include "common/app/cli.hpp"
#include "common/scene/scene.hpp"
#include "common/vk/device.hpp"
#include "shadow_cache.hpp"
#include "shadow_pass.hpp"

// Each option's values, the default first; the options' strings are made from them.
inline const std::vector<uint32_t> kCascadeCounts{3, 1, 2, 4};
inline const std::vector<uint32_t> kShadowMapSizes{2048, 512, 1024, 4096};
const common::Choice& cascadesChoice();
const common::Choice& shadowMapSizeChoice();
const common::Choice& shadowFarChoice();
const common::Choice& shadowRedrawChoice();

// What the options ask for, on this device.
struct ShadowOptions {
    CascadeSettings settings;                      // --cascades, --shadow-map-size; reachCasters
    bool fitFar = true;                            // --shadow-far scene
    ShadowRedraw redraw = ShadowRedraw::Scrolled;  // --shadow-redraw
};
ShadowOptions shadowOptions(const common::Options& options, const common::Device& device);

// The overlay's shadow controls: the book's cascade debug view (a switch in its settings file,
// view `cascadesView`), where the last cascade ends, whether cascades are drawn only when they
// changed; and per cascade, the slice it covers, its texel in the world and how often it was drawn.
void shadowWidgets(int* view, int cascadesView, ShadowOptions& options, const std::vector<Cascade>& cascades,
                   ShadowPass& pass);

// --benchmark's rows: a row per cascade (the shadow pass draws them all at once, so the GPU times
// them together, on the "shadow" row) and whether the device clamps depth.
void addShadowInfo(std::vector<std::pair<std::string, std::string>>& info, const common::Device& device,
                   const std::vector<Cascade>& cascades, const ShadowCache& cache,
                   const std::vector<uint64_t>& firstFrameCost);
// The lines after a run: how often each cascade was drawn and what a frame drew of each; the
// fitted far plane's steps (`farSteps`: up, down).
void printShadowReport(const char* chapter, const ShadowCache& cache, uint32_t cascades,
                       const uint32_t farSteps[2]);
// --check-output: the last frame's sun (light `sun`, -1 for none) and cascades are finite
// numbers. A light direction or a cascade of NaN or infinity puts every pixel in shadow (or
// none), which no NaN in the image shows.
void checkShadowInputs(const char* chapter, const common::Scene& scene, int sun,
                       const std::vector<Cascade>& cascades);
