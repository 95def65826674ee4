// --benchmark [--warmup N] [--frames N] [--json FILE]: frame times on the CPU and, from timestamp queries, on
// the GPU for the whole frame and for each pass; median / p95 / min / max as a table on stdout and, with
// --json FILE, as JSON.
//
// A chapter creates a GpuTimer with the names of its passes, calls beginGpuTimer / markGpuPass /
// endGpuTimer while recording a frame, and hands each finished frame's numbers to a FrameStats.
// Queries live per frame in flight and are read after that slot's fence has signalled, so reading
// them never waits for the GPU.
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/app/cli.hpp"
#include "common/vk/device.hpp"
#include "common/wnd/target.hpp"

namespace common {

struct GpuTimer {
    bool supported = false;           // the queue family has timestamps (timestampValidBits > 0)
    double nanosecondsPerTick = 1.0;  // VkPhysicalDeviceLimits::timestampPeriod
    uint64_t validMask = ~0ull;
    VkQueryPool pool = VK_NULL_HANDLE;
    std::vector<std::string> passes;
    uint32_t queriesPerFrame = 0;  // one before the first pass, one after each
    struct Slot {
        bool written = false;  // queries recorded since the last read
        uint32_t frame = 0;    // the frame whose queries these are
    };
    std::vector<Slot> slots;     // per frame in flight
    std::vector<double> latest;  // the last frame read, in ms: whole frame, then each pass (the GUI shows it)
    uint32_t latestFrame = 0;
};

GpuTimer createGpuTimer(const Device& device, uint32_t framesInFlight, std::vector<std::string> passes);
void destroyGpuTimer(const Device& device, GpuTimer& timer);
// Resets this slot's queries and writes the start timestamp of frame `frame` (record before the
// first pass).
void beginGpuTimer(GpuTimer& timer, VkCommandBuffer cmd, uint32_t slot, uint32_t frame);
// Writes the timestamp that ends pass `pass` (record after it).
void markGpuPass(const GpuTimer& timer, VkCommandBuffer cmd, uint32_t slot, uint32_t pass);
struct FrameStats;
// After the slot's fence: adds the slot's last frame's milliseconds (whole frame, then each pass)
// to `stats`; nothing when timestamps are unsupported or nothing was recorded.
void readGpuTimer(const Device& device, GpuTimer& timer, uint32_t slot, FrameStats& stats);

// Collects the measured frames of a run.
struct FrameStats {
    uint32_t warmup = 0;         // frames before the measured ones
    std::filesystem::path json;  // where to write the JSON report; empty: none
    std::vector<std::string> passes;
    std::vector<double> cpuMs;               // per measured frame
    std::vector<double> updateMs, recordMs;  // per measured frame: the update step, the recording
    std::vector<double> submitMs;            // per measured frame: the submission and the presentation
    std::vector<double> waitMs;              // per measured frame: the wait for the slot's fence
    std::vector<std::vector<double>> gpuMs;  // per measured frame: whole frame, then each pass
    double startupMs = 0;                    // process start (runChapter) to the first presented frame
    bool gpuTimestamps = false;
};

FrameStats createFrameStats(const Options& options, std::vector<std::string> passes);
// Frame `frame` took `ms` on the CPU (counted once past the warm-up).
void addCpuFrame(FrameStats& stats, uint32_t frame, double ms);
// Frame `frame`'s update step (the chapter's: uniforms, instance data), the recording of its
// passes (the GUI's excluded), and its submission and presentation (the GUI's recording included)
// took these many CPU milliseconds.
void addCpuSteps(FrameStats& stats, uint32_t frame, double updateMs, double recordMs, double submitMs);
// Frame `frame` waited this long for its slot's fence (the GPU still drawing the frame before).
void addFenceWait(FrameStats& stats, uint32_t frame, double ms);
// The table on stdout, and the JSON file. `info` names what was measured (device, driver,
// resolution, layout, frames in flight...).
void reportBenchmark(const FrameStats& stats, const std::vector<std::pair<std::string, std::string>>& info);

// What a benchmark ran on: chapter, device, driver, the Vulkan version and extensions the chapter's
// features came from, resolution, frames in flight, how it presented and in which format, the
// depth format (`depthFormat`, for the chapters that have depth), and the chapter's --choices.
std::vector<std::pair<std::string, std::string>> benchmarkInfo(const ChapterInfo& chapter,
                                                               const Options& options, const Device& device,
                                                               const Target& target,
                                                               VkFormat depthFormat = VK_FORMAT_UNDEFINED);

// The pipelines a scene chapter made at start-up, for the report: `scenePipelines` (one per
// material class the scene has) and how long making the passes took (`passesMs`: their pipelines,
// mostly -- a cold pipeline cache shows here).
void addPipelineInfo(std::vector<std::pair<std::string, std::string>>& info, size_t scenePipelines,
                     double passesMs);

}  // namespace common
