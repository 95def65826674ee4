// chapter-20: the book's Engine on two threads. The main thread reads the window's events, runs
// the input and the update, and writes the next frame's slot (its uniforms, its GlobalBuffers, its
// snapshot); a render thread records, submits and presents the frame before it. They meet once a
// frame: the main thread waits for the render thread's frame to be presented, then hands it the
// frame it has just written.
//
// Where the book's is fragile, and ours (docs/chapter-20.md, "Where we differ from the book"):
// - the render thread draws the frame the main thread wrote before (the book's draws the slot being
//   written); the main thread writes a slot only after the fence of the frame that last read it;
// - what recording reads of the update is the slot's (render.hpp's FrameSnapshot), never the live
//   camera, lights or clock;
// - every GLFW call is the main thread's; the render thread answers whether the window must be
//   remade, and the main thread remakes it while no frame is recorded, and writes again the slot of
//   a frame written for the old size;
// - a failure on either thread ends the run: the render thread's is handed to the main thread at
//   their next meeting and thrown there.
#pragma once

#include <cstdint>
#include <functional>

#include "common/app/frame_loop.hpp"

// What the chapter gives the loop, by the thread that runs it.
struct ThreadedSteps {
    // The main thread, while no frame is recorded (when the threads meet): live reload, the
    // overlay's widgets, what follows a new window size. As common::FrameSteps's.
    std::function<void(const common::ShaderReload& reload, common::PipelineSwap& swap)> remakePipelines;
    std::function<void()> overlay;
    std::function<void()> resize;
    // The main thread, while the render thread records the frame before: the keys and mouse (in a
    // window); what moves (`advance`: frame `frame`'s time and test motion); then what frame
    // `frame` draws, written to its slot `slot`, whose fence has signalled (`update`).
    // `waitForRender` waits until no frame is recorded (for what the update must change under the
    // render thread). When the window is made again before the frame is handed over, `update`
    // runs again for the new size (`advance` does not).
    std::function<void(GLFWwindow* window, float seconds, bool keys, bool mouse)> input;
    std::function<void(uint32_t frame)> advance;
    std::function<void(uint32_t frame, uint32_t slot, const std::function<void()>& waitForRender)> update;
    // The render thread: the frame's passes, from its slot (`frame.slot`) and what stays.
    std::function<void(common::FrameCommands& frame)> record;
};

// Frames until the last (--frames, the window closed, Ctrl+C), then vkDeviceWaitIdle; the render
// thread is joined before it returns or throws.
void runThreadedFrameLoop(common::RenderContext& context, const ThreadedSteps& steps);

// A test's switch (VKBOOK_TEST_RACE=camera, tests/chapters/chapter-20.cmake): the render thread
// reads the live camera, as the book's does -- a data race that ThreadSanitizer must report.
bool plantedCameraRace();
