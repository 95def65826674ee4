// Run control and the bookkeeping around each frame that is not drawing: how many frames a run
// draws (--frames), the scripted --resize, the --benchmark timestamps and statistics, and the
// --screenshot of the last frame. Each is one call in a chapter's frame loop, so the loop itself
// shows what the book's does: wait, acquire, record, submit, present.
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/app/benchmark.hpp"
#include "common/app/cli.hpp"
#include "common/core/stop.hpp"
#include "common/vk/device.hpp"
#include "common/wnd/target.hpp"

namespace common {

struct RunControl {
    uint32_t frameLimit = 0;                   // 0: until the window is closed
    std::optional<VkExtent2D> scriptedResize;  // --resize, applied at frame frameLimit / 2
    bool benchmark = false;
    bool timed = false;                // GPU timestamps recorded: --benchmark, or --gui (which shows them)
    std::filesystem::path screenshot;  // empty: none
    GpuTimer gpuTimer;                 // timestamps before the first pass and after each
    FrameStats stats;
    std::chrono::steady_clock::time_point frameStart;
    double lastCpuMs = 0.0;              // the last frame's CPU time (the GUI shows it)
    std::vector<std::string> passNames;  // the benchmark rows, also each pass's debug label
};

// `passes` names the passes whose GPU time --benchmark reports, in recording order.
RunControl createRunControl(const Options& options, const Device& device, std::vector<std::string> passes);
void destroyRunControl(const Device& device, RunControl& run);

// Starts frame `frame`: the scripted resize when it is due, the window's events. Returns true
// when this is the last frame (--frames reached, the window asked to close, or Ctrl+C / SIGTERM).
bool beginFrame(RunControl& run, Target& target, uint32_t frame);
// After the fence of frame-in-flight `slot`: the GPU times of the frame it last ran (--benchmark,
// --gui); run.gpuTimer.latest holds them.
void collectGpuTimes(RunControl& run, const Device& device, uint32_t slot);
// While recording (--benchmark, --gui): the frame's first timestamp, and one after pass `pass`.
void timeFrameStart(RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t frame);
void timePassEnd(const RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t pass);
// Around the commands of pass `pass`: a debug label named like its benchmark row, which graphics
// debuggers show as the pass (common/vk/debug_names.hpp); endPass also records timePassEnd.
void beginPass(const RunControl& run, VkCommandBuffer cmd, uint32_t pass);
void endPass(const RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t pass);
// After the last frame's submission, before it is presented: the --screenshot of that image.
void screenshotLastFrame(const RunControl& run, const Device& device, const Target& target,
                         uint32_t imageIndex);
// After presenting: the startup time (first frame) and the frame's CPU time.
void endFrame(RunControl& run, uint32_t frame);
// The same with the frame's CPU time given (chapter-20: the time between two frames handed to the
// render thread).
void endFrame(RunControl& run, uint32_t frame, double cpuMs);
// After the loop and vkDeviceWaitIdle: the remaining GPU times and the --benchmark report, with
// `info` saying what was measured (common::benchmarkInfo, plus anything chapter-specific).
void reportRun(RunControl& run, const Device& device,
               const std::vector<std::pair<std::string, std::string>>& info);

}  // namespace common
