// The command line every chapter shares, and the exit codes it promises:
//   0 success; 1 any other failure; 2 bad usage or bad input (one line on stderr naming the
//   problem); 3 the validation layer reported at least one warning or error.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace common {

inline constexpr uint32_t kMaxWindowDimension = 16384;  // further checked against the device

struct Options {
    bool headless = false;
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;               // 0: the default, 1 frame headless, until closed in a window
    std::filesystem::path screenshot;  // empty: no screenshot
    std::string device;                // substring of the device name; empty: best device
    bool validation = false;
    std::optional<VkExtent2D> resizeTo;  // testing aid: resize the target half-way through --frames
    bool help = false;
};

// Parses argv; throws InputError with a one-line message on any bad argument.
Options parseCommandLine(int argc, const char* const* argv);

// How many frames this run renders: --frames, or the default for the mode (0 = until closed).
uint32_t frameCount(const Options& options);

// Runs a chapter: parses the command line, prints --help, calls `chapter`, and maps what
// happened to the exit codes above. Every chapter's main() is this one call.
int runChapter(int argc, const char* const* argv, const char* name, const char* summary,
               const std::function<void(const Options&)>& chapter);

}  // namespace common
