// Around chapter-16's shadow pass (shadow_controls.hpp).
#include "shadow_controls.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/core/check.hpp"

namespace {

std::vector<std::string> texts(const std::vector<uint32_t>& values) {
    std::vector<std::string> result;
    for (uint32_t value : values) result.push_back(std::to_string(value));
    return result;
}

uint32_t chosen(const common::Options& options, const common::Choice& choice) {
    auto found = options.choices.find(choice.name);
    return found == options.choices.end() ? 0u : found->second;
}

}  // namespace

const common::Choice& cascadesChoice() {
    static const common::Choice choice{"cascades", texts(kCascadeCounts),
                                       "cascades of the sun's shadow map (the book's: 3)"};
    return choice;
}

const common::Choice& shadowMapSizeChoice() {
    static const common::Choice choice{"shadow-map-size", texts(kShadowMapSizes),
                                       "texels along each side of a cascade's shadow map"};
    return choice;
}

const common::Choice& shadowFarChoice() {
    static const common::Choice choice{
        "shadow-far",
        {"scene", "view"},
        "where the last cascade ends: where the scene's bounds end (in steps), or the view's far plane"};
    return choice;
}

const common::Choice& shadowRedrawChoice() {
    static const common::Choice choice{
        "shadow-redraw",
        {"scrolled", "scrolled-together", "changed", "always"},  // ShadowRedraw's order
        "what a frame draws of the shadow map: only the bands a cascade's move exposed, moving casters "
        "drawn apart (scrolled); the same with moving casters in the cached map (scrolled-together); a "
        "cascade whole when what it sees changed (changed); every cascade every frame (always)"};
    return choice;
}

ShadowOptions shadowOptions(const common::Options& options, const common::Device& device) {
    ShadowOptions result;
    result.settings.count = kCascadeCounts[chosen(options, cascadesChoice())];
    result.settings.mapSize = kShadowMapSizes[chosen(options, shadowMapSizeChoice())];
    // No depth clamping on this device: the cascades reach toward the sun as far as the scene does.
    result.settings.reachCasters = !device.depthClamp;
    result.fitFar = chosen(options, shadowFarChoice()) == 0;
    result.redraw = ShadowRedraw(chosen(options, shadowRedrawChoice()));
    return result;
}

void shadowWidgets(int* view, int cascadesView, ShadowOptions& options, const std::vector<Cascade>& cascades,
                   ShadowPass& pass) {
    ImGui::Separator();
    ImGui::TextUnformatted("Shadows");
    bool debug = *view == cascadesView;
    if (ImGui::Checkbox("show cascades", &debug)) *view = debug ? cascadesView : 0;
    ImGui::Checkbox("fit last cascade to the scene", &options.fitFar);
    int form = int(options.redraw);
    if (ImGui::Combo("redraw", &form, "scrolled\0scrolled-together\0changed\0always\0")) {
        options.redraw = ShadowRedraw(form);
        invalidateShadowCache(pass, options.redraw);
    }
    const ShadowCache& cache = pass.cache;
    for (size_t i = 0; i < cascades.size(); ++i) {
        const Cascade& cascade = cascades[i];
        ImGui::Text("cascade %zu: %.2f..%.2f m, texel %.1f mm, drawn %llu times", i, cascade.splitNear,
                    cascade.splitFar, cascade.texel * 1000.0f,
                    static_cast<unsigned long long>(cache.redraws[i]));
    }
}

void addShadowInfo(std::vector<std::pair<std::string, std::string>>& info, const common::Device& device,
                   const std::vector<Cascade>& cascades, const ShadowCache& cache,
                   const std::vector<uint64_t>& firstFrameCost) {
    // Without depth clamping the cascades reach toward the sun as far as the scene does.
    info.push_back({"depth_clamp", device.depthClamp ? "yes" : "no: cascades reach the scene's casters"});
    // Per cascade: the slice it covers, its texel's size in the world, in how many frames it was
    // drawn (and drawn whole), and what it cost a frame on average: texels cleared and drawn,
    // draws and triangles submitted.
    double frames = double(std::max<uint64_t>(cache.frames, 1));
    for (size_t i = 0; i < cascades.size(); ++i) {
        const Cascade& cascade = cascades[i];
        char text[256];
        std::snprintf(
            text, sizeof(text),
            "%.2f..%.2f m, texel %.2f mm, drawn in %llu of %llu frames (%llu whole); a frame: "
            "%.0f texels, %.1f draws, %.0f triangles",
            cascade.splitNear, cascade.splitFar, cascade.texel * 1000.0f,
            static_cast<unsigned long long>(cache.redraws[i]), static_cast<unsigned long long>(cache.frames),
            static_cast<unsigned long long>(cache.wholeRedraws[i]), double(cache.texels[i]) / frames,
            double(cache.draws[i]) / frames, double(cache.triangles[i]) / frames);
        info.push_back({"shadow_cascade_" + std::to_string(i), text});
    }
    // The bound of the first frame's fragments checked at start-up (common/scene/frame_cost.hpp).
    std::string bound;
    for (uint64_t fragments : firstFrameCost)
        bound += (bound.empty() ? "" : ", ") + std::to_string(fragments);
    info.push_back({"first_frame_fragments_bound", bound + " (the view, then each cascade)"});
}

void printShadowReport(const char* chapter, const ShadowCache& cache, uint32_t cascades,
                       const uint32_t farSteps[2]) {
    // How often each cascade was drawn (anything: whole, bands, moving casters), and drawn whole:
    // once for a still camera, more as it moves; then what a frame drew of each, on average.
    std::string drawn, whole, texels, draws, moving;
    double frames = double(std::max<uint64_t>(cache.frames, 1));
    auto append = [](std::string& list, const char* format, double value) {
        char text[64];
        std::snprintf(text, sizeof(text), format, value);
        if (!list.empty()) list += ", ";
        list += text;
    };
    for (uint32_t i = 0; i < cascades; ++i) {
        append(drawn, "%.0f", double(cache.redraws[i]));
        append(whole, "%.0f", double(cache.wholeRedraws[i]));
        append(texels, "%.0f", double(cache.texels[i]) / frames);
        append(draws, "%.1f", double(cache.draws[i]) / frames);
        append(moving, "%.0f", double(cache.movingFrames[i]));
    }
    std::printf("%s: cascades drawn %s times in %llu frames (whole %s)\n", chapter, drawn.c_str(),
                static_cast<unsigned long long>(cache.frames), whole.c_str());
    std::printf("%s: a frame drew %s texels and %s draws per cascade; %llu draws culled\n", chapter,
                texels.c_str(), draws.c_str(), static_cast<unsigned long long>(cache.culled));
    uint64_t movingAny = 0;
    for (uint64_t count : cache.movingFrames) movingAny += count;
    if (movingAny > 0) std::printf("%s: moving casters drawn apart in %s frames\n", chapter, moving.c_str());
    if (farSteps[0] + farSteps[1] > 0)
        std::printf("%s: the fitted far plane stepped up %u and down %u times\n", chapter, farSteps[0],
                    farSteps[1]);
}

void checkShadowInputs(const char* chapter, const common::Scene& scene, int sun,
                       const std::vector<Cascade>& cascades) {
    auto finite = [](const glm::mat4& m) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (!std::isfinite(m[i][j])) return false;
        return true;
    };
    if (sun >= 0) {
        float length = glm::length(scene.lights[size_t(sun)].direction);
        if (!std::isfinite(length) || !(length > 0.0f))
            throw common::Failure("--check-output: the sun's direction is not finite and non-zero");
    }
    for (size_t i = 0; i < cascades.size(); ++i) {
        const Cascade& cascade = cascades[i];
        if (!finite(cascade.viewProjection) || !std::isfinite(cascade.texel) || !(cascade.texel > 0.0f) ||
            !std::isfinite(cascade.splitFar) || !(cascade.splitFar > cascade.splitNear))
            throw common::Failure("--check-output: cascade " + std::to_string(i) +
                                  " is not finite (its matrix, texel or slice)");
    }
    std::printf("%s: output check: the sun and %zu cascades finite\n", chapter, cascades.size());
}
