// Run control and per-frame bookkeeping.
#include "common/app/run_control.hpp"

#include <cstdio>
#include <cstdlib>

#include "common/vk/debug_names.hpp"
#include "common/vk/screenshot.hpp"

namespace common {

RunControl createRunControl(const Options& options, const Device& device, std::vector<std::string> passes) {
    RunControl run;
    run.passNames = passes;
    run.frameLimit = frameCount(options);
    run.scriptedResize = options.resizeTo;
    run.benchmark = options.benchmark;
    run.timed = options.benchmark || options.switches.count("gui") != 0;
    run.screenshot = options.screenshot;
    run.gpuTimer = createGpuTimer(device, options.framesInFlight, passes);
    run.stats = createFrameStats(options, std::move(passes));
    return run;
}

void destroyRunControl(const Device& device, RunControl& run) {
    destroyGpuTimer(device, run.gpuTimer);
    run = {};
}

bool beginFrame(RunControl& run, Target& target, uint32_t frame) {
    run.frameStart = std::chrono::steady_clock::now();
    if (run.scriptedResize && frame == run.frameLimit / 2) {
        requestTargetSize(target, *run.scriptedResize);
        run.scriptedResize.reset();
    }
    bool closing = pollTarget(target) || stopRequested();
    return closing || (run.frameLimit != 0 && frame + 1 >= run.frameLimit);
}

void collectGpuTimes(RunControl& run, const Device& device, uint32_t slot) {
    if (run.timed) readGpuTimer(device, run.gpuTimer, slot, run.stats);
}

void timeFrameStart(RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t frame) {
    if (run.timed) beginGpuTimer(run.gpuTimer, cmd, slot, frame);
}

void timePassEnd(const RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t pass) {
    if (run.timed) markGpuPass(run.gpuTimer, cmd, slot, pass);
}

void beginPass(const RunControl& run, VkCommandBuffer cmd, uint32_t pass) {
    beginLabel(cmd, run.passNames.at(pass));
}

void endPass(const RunControl& run, VkCommandBuffer cmd, uint32_t slot, uint32_t pass) {
    endLabel(cmd);
    timePassEnd(run, cmd, slot, pass);
}

void screenshotLastFrame(const RunControl& run, const Device& device, const Target& target,
                         uint32_t imageIndex) {
    if (run.screenshot.empty()) return;
    saveScreenshot(device, target.images[imageIndex], target.format, target.extent, target.presentLayout,
                   run.screenshot);
}

void endFrame(RunControl& run, uint32_t frame) {
    endFrame(
        run, frame,
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - run.frameStart).count());
}

void endFrame(RunControl& run, uint32_t frame, double cpuMs) {
    if (frame == 0) run.stats.startupMs = millisecondsSinceStart();
    // For test scripts that drive a window (tests/desktops/frames.sh): with VKBOOK_TEST_EVENTS set,
    // each frame's end is a line, so that a script waits for frames, never for a guessed time.
    static const bool testEvents = std::getenv("VKBOOK_TEST_EVENTS") != nullptr;
    if (testEvents) {
        std::printf("test-event: frame %u ended\n", frame);
        std::fflush(stdout);
    }
    run.lastCpuMs = cpuMs;
    addCpuFrame(run.stats, frame, run.lastCpuMs);
}

void reportRun(RunControl& run, const Device& device,
               const std::vector<std::pair<std::string, std::string>>& info) {
    if (!run.benchmark) return;
    for (uint32_t slot = 0; slot < run.gpuTimer.slots.size(); ++slot)
        readGpuTimer(device, run.gpuTimer, slot, run.stats);
    reportBenchmark(run.stats, info);
}

}  // namespace common
