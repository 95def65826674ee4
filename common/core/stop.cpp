// Stopping a run (stop.hpp).
#include "common/core/stop.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#if !defined(_WIN32)
#include <unistd.h>
#endif

#include "common/core/files.hpp"

namespace common {

namespace {

// Ctrl+C or a TERM signal ends the run at the next frame like closing the window does, so a
// headless run of many frames still writes its --screenshot (and a live-reload test can end one).
// The handler only stores the signal (a lock-free atomic: async-signal-safe); a watchdog thread
// cuts the run short if the frame or the load does not end in time.
std::atomic<int> gInterrupted{0};  // the signal; negative: a window closed (kCloseNow: cut short now)
constexpr int kCloseNow = -2;
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void interrupt(int signal) {
    gInterrupted.store(signal);
}

void watchdog(std::string name, int graceMs) {
    while (gInterrupted.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const auto seen = std::chrono::steady_clock::now();  // within 10 ms of the signal or the close
    static const bool testEvents = std::getenv("VKBOOK_TEST_EVENTS") != nullptr;
    if (testEvents) {  // when, on the wall clock, for a test that timed its own signal or key press
        const long long epochMs = std::chrono::duration_cast<std::chrono::milliseconds>(
                                      std::chrono::system_clock::now().time_since_epoch())
                                      .count();
        std::string event = "test-event: stop seen at " + std::to_string(epochMs) + " ms\n";
#if defined(_WIN32)
        std::fputs(event.c_str(), stdout);
#else
        [[maybe_unused]] ssize_t written = ::write(1, event.data(), event.size());
#endif
    }
    if (gInterrupted.load() != kCloseNow) std::this_thread::sleep_for(std::chrono::milliseconds(graceMs));
    const int signal = gInterrupted.load();
    removeRegisteredTemporaries();
    // How long the stop took this process, said in the line: the process's end comes after it, as
    // soon as the system gives its threads the CPU to end (seconds on a loaded machine).
    const long long ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - seen)
            .count();
    // write(), not stdio: the main thread may hold stderr's lock, stuck on a full pipe.
    std::string line = name + (signal > 0 ? ": interrupted" : ": closed") +
                       " in the middle of a frame or a load; stopped after " + std::to_string(ms) + " ms\n";
#if defined(_WIN32)
    std::fputs(line.c_str(), stderr);
#else
    [[maybe_unused]] ssize_t written = ::write(2, line.data(), line.size());
#endif
    std::fflush(stdout);  // what the run printed so far (stdio locks each stream: safe from here)
    std::_Exit(signal > 0 ? 128 + signal : 0);  // a closed window: the run's normal end
}

}  // namespace

int stopGraceMs() {
    static const int grace = [] {
        const char* text = std::getenv("VKBOOK_STOP_GRACE_MS");
        if (!text || !*text) return kStopGraceMs;
        char* end = nullptr;
        long value = std::strtol(text, &end, 10);
        return *end == '\0' && value >= 1 && value <= 60000 ? int(value) : kStopGraceMs;
    }();
    return grace;
}

void watchForStop(const char* chapterName) {
    static bool started = false;
    gInterrupted.store(0);
    std::signal(SIGINT, interrupt);
    std::signal(SIGTERM, interrupt);
    if (started) return;
    started = true;
    std::thread(watchdog, std::string(chapterName), stopGraceMs()).detach();
    // For test scripts (tests/reliability/stop_run.sh): from here on a signal stops the run with
    // its one line, so a script signals after this line, never after a guessed time.
    if (std::getenv("VKBOOK_TEST_EVENTS")) {
        std::printf("test-event: stop handlers installed\n");
        std::fflush(stdout);
    }
}

bool stopRequested() {
    return gInterrupted.load() != 0;
}

void requestStop(bool now) {
    int none = 0;
    gInterrupted.compare_exchange_strong(none, now ? kCloseNow : -1);  // negative: no signal, exit 0
}

}  // namespace common
