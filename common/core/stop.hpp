// Stopping a run: Ctrl+C, SIGTERM, or a window closed while a frame is still running.
#pragma once

namespace common {

// Ctrl+C (SIGINT) and SIGTERM, from the start of a run (runChapter calls it before the chapter
// loads anything): the run ends at the next frame, as when its window closes (exit 0, the
// --screenshot written). If it has not ended kStopGraceMs later -- a long frame, a long load --
// it is cut short: the temporaries being written are removed (common/core/files.hpp), one line says
// so, and the process exits at once with 128 + the signal (130 for Ctrl+C, 143 for SIGTERM), as
// a shell reports a process a signal ended. Nothing else is left: the device and its memory
// belong to the process.
inline constexpr int kStopGraceMs = 400;
// The grace in force: kStopGraceMs, or the environment's VKBOOK_STOP_GRACE_MS (1 to 60000; the
// live-reload tests lengthen it, whose frames under synchronization validation on a loaded
// machine may take longer).
int stopGraceMs();
void watchForStop(const char* chapterName);
// Whether a stop was asked for (the signal, or requestStop).
bool stopRequested();
// A window closed while a frame is still running, kStopGraceMs after the close (common/wnd/target.cpp
// waits that long for the frame): the run is cut short at once (exit 0: a closed window is the
// run's normal end).
void requestStop(bool now);

}  // namespace common
