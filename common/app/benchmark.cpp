// Benchmark mode: timestamp queries, statistics, the report.
#include "common/app/benchmark.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/formats.hpp"

namespace common {

GpuTimer createGpuTimer(const Device& device, uint32_t framesInFlight, std::vector<std::string> passes) {
    GpuTimer timer;
    timer.passes = std::move(passes);
    timer.queriesPerFrame = uint32_t(timer.passes.size()) + 1;
    timer.slots.assign(framesInFlight, {});
    timer.supported = device.timestampValidBits > 0 && device.properties.limits.timestampPeriod > 0.0f;
    if (!timer.supported) return timer;
    timer.nanosecondsPerTick = device.properties.limits.timestampPeriod;
    timer.validMask = device.timestampValidBits >= 64 ? ~0ull : (1ull << device.timestampValidBits) - 1;
    VkQueryPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
        .queryType = VK_QUERY_TYPE_TIMESTAMP,
        .queryCount = timer.queriesPerFrame * framesInFlight,
    };
    VK_CHECK(vkCreateQueryPool(device.handle, &info, nullptr, &timer.pool));
    nameObject(device.handle, timer.pool, "pass timestamps");
    return timer;
}

void destroyGpuTimer(const Device& device, GpuTimer& timer) {
    if (timer.pool != VK_NULL_HANDLE) vkDestroyQueryPool(device.handle, timer.pool, nullptr);
    timer = {};
}

void beginGpuTimer(GpuTimer& timer, VkCommandBuffer cmd, uint32_t slot, uint32_t frame) {
    if (!timer.supported) return;
    timer.slots[slot].frame = frame;
    uint32_t first = slot * timer.queriesPerFrame;
    vkCmdResetQueryPool(cmd, timer.pool, first, timer.queriesPerFrame);
    // TOP_OF_PIPE: written once everything before it on the queue has started, i.e. the frame's start.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timer.pool, first);
    timer.slots[slot].written = true;
}

void markGpuPass(const GpuTimer& timer, VkCommandBuffer cmd, uint32_t slot, uint32_t pass) {
    if (!timer.supported) return;
    // BOTTOM_OF_PIPE: written once all earlier commands have finished, i.e. the pass's end.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timer.pool,
                        slot * timer.queriesPerFrame + pass + 1);
}

void readGpuTimer(const Device& device, GpuTimer& timer, uint32_t slot, FrameStats& stats) {
    if (!timer.supported || !timer.slots[slot].written) return;
    std::vector<uint64_t> ticks(timer.queriesPerFrame);
    VkResult result = vkGetQueryPoolResults(device.handle, timer.pool, slot * timer.queriesPerFrame,
                                            timer.queriesPerFrame, ticks.size() * sizeof(uint64_t),
                                            ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
    timer.slots[slot].written = false;
    if (result == VK_NOT_READY) return;
    VK_CHECK_RESULT(result, "vkGetQueryPoolResults");
    auto ms = [&](uint64_t from, uint64_t to) {
        return double((to - from) & timer.validMask) * timer.nanosecondsPerTick * 1e-6;
    };
    std::vector<double> milliseconds{ms(ticks.front(), ticks.back())};
    for (size_t pass = 0; pass < timer.passes.size(); ++pass)
        milliseconds.push_back(ms(ticks[pass], ticks[pass + 1]));
    timer.latest = milliseconds;
    timer.latestFrame = timer.slots[slot].frame;
    if (timer.slots[slot].frame < stats.warmup) return;
    stats.gpuMs.push_back(milliseconds);
}

FrameStats createFrameStats(const Options& options, std::vector<std::string> passes) {
    FrameStats stats;
    stats.warmup = options.warmup;
    stats.json = options.json;
    stats.passes = std::move(passes);
    return stats;
}

void addCpuFrame(FrameStats& stats, uint32_t frame, double ms) {
    if (frame >= stats.warmup) stats.cpuMs.push_back(ms);
}

void addCpuSteps(FrameStats& stats, uint32_t frame, double updateMs, double recordMs, double submitMs) {
    if (frame < stats.warmup) return;
    stats.updateMs.push_back(updateMs);
    stats.recordMs.push_back(recordMs);
    stats.submitMs.push_back(submitMs);
}

void addFenceWait(FrameStats& stats, uint32_t frame, double ms) {
    if (frame >= stats.warmup) stats.waitMs.push_back(ms);
}

namespace {

struct Summary {
    double median = 0, p95 = 0, min = 0, max = 0;
};

// Nearest-rank percentiles of the measured frames.
Summary summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    auto rank = [&](double p) {
        return values[std::min(values.size() - 1, size_t(p * double(values.size())))];
    };
    return {rank(0.5), rank(0.95), values.front(), values.back()};
}

nlohmann::json toJson(const Summary& s, const std::vector<double>& frames) {
    return {{"median", s.median}, {"p95", s.p95}, {"min", s.min}, {"max", s.max}, {"frames", frames}};
}

}  // namespace

void reportBenchmark(const FrameStats& stats, const std::vector<std::pair<std::string, std::string>>& info) {
    nlohmann::json report;
    for (const auto& [key, value] : info) {
        std::printf("%-18s %s\n", key.c_str(), value.c_str());
        report[key] = value;
    }
    std::printf("%-18s %zu measured after %u warm-up\n", "frames", stats.cpuMs.size(), stats.warmup);
    std::printf("%-18s %.1f ms\n", "startup", stats.startupMs);
    report["measured_frames"] = stats.cpuMs.size();
    report["warmup_frames"] = stats.warmup;
    report["startup_ms"] = stats.startupMs;

    std::printf("\n%-18s %10s %10s %10s %10s\n", "ms", "median", "p95", "min", "max");
    Summary cpu = summarize(stats.cpuMs);
    std::printf("%-18s %10.3f %10.3f %10.3f %10.3f\n", "CPU frame", cpu.median, cpu.p95, cpu.min, cpu.max);
    report["cpu_frame_ms"] = toJson(cpu, stats.cpuMs);
    for (const auto& [name, key, values] :
         {std::tuple{"CPU update", "cpu_update_ms", &stats.updateMs},
          std::tuple{"CPU record", "cpu_record_ms", &stats.recordMs},
          std::tuple{"CPU submit", "cpu_submit_ms", &stats.submitMs},
          std::tuple{"CPU fence wait", "cpu_fence_wait_ms", &stats.waitMs}}) {
        if (values->empty()) continue;
        Summary step = summarize(*values);
        std::printf("%-18s %10.3f %10.3f %10.3f %10.3f\n", name, step.median, step.p95, step.min, step.max);
        report[key] = toJson(step, *values);
    }
    bool timestamps = !stats.gpuMs.empty();
    report["gpu_timestamps"] = timestamps;
    if (timestamps) {
        for (size_t column = 0; column <= stats.passes.size(); ++column) {
            std::vector<double> values;
            for (const std::vector<double>& frame : stats.gpuMs) values.push_back(frame[column]);
            Summary s = summarize(values);
            std::string name = column == 0 ? "frame" : stats.passes[column - 1];
            std::printf("%-18s %10.3f %10.3f %10.3f %10.3f\n", ("GPU " + name).c_str(), s.median, s.p95,
                        s.min, s.max);
            report["gpu_ms"][name] = toJson(s, values);
        }
    } else {
        std::printf("GPU times: this device's queue has no timestamps\n");
    }
    if (!stats.json.empty()) {
        std::ofstream out(stats.json);
        out << report.dump(2) << "\n";
        if (!out) throw Failure("cannot write '" + utf8(stats.json) + "'");
    }
}

void addPipelineInfo(std::vector<std::pair<std::string, std::string>>& info, size_t scenePipelines,
                     double passesMs) {
    info.push_back({"scene_pipelines", std::to_string(scenePipelines)});
    char ms[32];
    std::snprintf(ms, sizeof(ms), "%.1f ms", passesMs);
    info.push_back({"passes_startup", ms});
}

std::vector<std::pair<std::string, std::string>> benchmarkInfo(const ChapterInfo& chapter,
                                                               const Options& options, const Device& device,
                                                               const Target& target, VkFormat depthFormat) {
    std::vector<std::pair<std::string, std::string>> info = {
        {"chapter", chapter.name},
        {"device", device.properties.deviceName},
        {"driver", device.driver},
        {"resolution", std::to_string(target.extent.width) + "x" + std::to_string(target.extent.height)},
        {"frames_in_flight", std::to_string(options.framesInFlight)},
        {"present",
         !target.window
             ? "headless"
             : std::string(target.vsync ? "window, vsync" : "window, no vsync") +
                   (device.swapchainMaintenance1 ? ", present fences (VK_EXT_swapchain_maintenance1)" : "")},
        {"target_format", formatName(target.format) + ", " + colorSpaceName(target.colorSpace)},
        {"vulkan", device.features},
    };
    if (depthFormat != VK_FORMAT_UNDEFINED) info.push_back({"depth_format", formatName(depthFormat)});
    for (const Choice& choice : chapter.choices)
        if (!choice.values.empty())
            info.push_back(
                {choice.name,
                 choice.values[options.choices.count(choice.name) ? options.choices.at(choice.name) : 0]});
    info.push_back({"command", options.command});
    return info;
}

}  // namespace common
