// The command line every chapter shares, and the exit codes it promises:
//   0 success; 1 any other failure; 2 bad usage or bad input (one line on stderr naming the
//   problem); 3 the validation layer reported at least one warning or error.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/core/options.hpp"

namespace common {

// A chapter-specific option with a fixed set of values, the first the default:
// {"gbuffer", {"book", "reference", "compact"}, "the G-buffer layout"} accepts --gbuffer compact.
// With no values it takes any non-empty value (a path): {"dump", {}, "..."} accepts --dump DIR.
struct Choice {
    std::string name;
    std::vector<std::string> values;
    std::string help;
};

// What a chapter is, for --help and for the options only some chapters take.
struct ChapterInfo {
    const char* name;     // "chapter-06"
    const char* summary;  // one line for --help
    // The attachments --view can show, the final image first; empty for chapters without a
    // scene, which then refuse --scene, --model and --view.
    std::vector<std::string> views;
    // Chapter-specific on/off options, each with its --help line: {"fxaa", "anti-alias with FXAA"}.
    std::vector<std::pair<std::string, std::string>> switches = {};
    std::vector<Choice> choices = {};
};

// --pipelines, for the chapters that draw scenes (10 on): "specialised" (the default) makes the
// pipelines for what the scene holds -- one per material class its materials have, the light
// pass for its lights of each kind -- so features a scene does not use cost nothing; "generic"
// makes one set for any scene, which asks each material's flags and each light's kind as it runs
// (to measure what specialising saves).
inline const Choice kPipelinesChoice{
    "pipelines",
    {"specialised", "generic"},
    "pipelines made for the scene's material classes and lights, or generic ones that ask as they run"};
bool genericPipelines(const Options& options);

// Parses argv with CLI11, each option bound to its field and each value checked as it is given;
// throws InputError with a one-line message naming the first bad argument.
Options parseCommandLine(int argc, const char* const* argv, const ChapterInfo& chapter);

// How many frames this run renders: --frames, or the default for the mode (0 = until closed).
uint32_t frameCount(const Options& options);

// Runs a chapter: parses the command line, prints --help, calls `chapter`, and maps what
// happened to the exit codes above. Every chapter's main() is this one call.
int runChapter(int argc, const char* const* argv, const ChapterInfo& info,
               const std::function<void(const Options&)>& chapter);

// Milliseconds since the process started (more exactly: since its static initialisation).
double millisecondsSinceStart();

}  // namespace common
