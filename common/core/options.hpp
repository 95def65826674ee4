// The options of a run, as the command line gives them (common/app/cli.cpp parses them): a
// plain struct every layer may read -- the window and the scene take their sizes and files from
// it -- so that reading them does not mean depending on the parser.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace common {

inline constexpr uint32_t kMaxWindowDimension = 16384;  // further checked against the device

struct Options {
    bool headless = false;
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;               // 0: the default, 1 frame headless, until closed in a window
    uint32_t framesInFlight = 2;       // frames the CPU may record while the GPU works on earlier ones
    std::filesystem::path screenshot;  // empty: no screenshot
    std::string device;                // substring of the device name; empty: best device
    bool validation = false;
    std::optional<VkExtent2D> resizeTo;  // testing aid: resize the target half-way through --frames
    std::optional<VkFormat>
        targetFormat;                 // --target-format: the presented images' format (common/vk/formats.hpp)
    std::filesystem::path shaderDir;  // --shader-dir: shader sources to compile and watch
    bool help = false;
    // --benchmark: render --warmup frames, then --frames measured ones (default 100), no vsync.
    bool benchmark = false;
    uint32_t warmup = 10;
    std::filesystem::path json;  // --json FILE: the benchmark report as JSON
    // Chapters that render scenes (chapter-10 on):
    std::filesystem::path scene;              // --scene FILE.json
    std::filesystem::path model;              // --model FILE (.obj, .gltf, .glb)
    std::filesystem::path bookScene;          // --book-scene PATH (the book's clone, or its Sponza.gltf)
    uint32_t view = 0;                        // --view: index into ChapterInfo::views (0 = the final image)
    std::set<std::string> switches;           // chapter-specific on/off options given, e.g. "fxaa" for --fxaa
    std::map<std::string, uint32_t> choices;  // chapter-specific --NAME VALUE: index of VALUE (0 default)
    std::map<std::string, std::string> values;  // chapter-specific --NAME VALUE of a free-form choice
    std::string command;  // the command line as given (program name without its directory), for reports
};

}  // namespace common
