// chapter-20: the book's Engine on two threads (frame_threads.hpp).
#include "frame_threads.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/stop.hpp"

namespace {

//> messages
// What the main thread hands the render thread: a frame whose slot it has written.
struct FrameJob {
    uint32_t frame = 0;
    uint32_t slot = 0;
    bool last = false;              // the run's last frame: --screenshot takes its image
    ImDrawData* overlay = nullptr;  // --gui: the overlay's lists, kept until the next meeting
    double mainMs = 0.0;            // the main thread's time on it: input and update
    uint64_t target = 0;            // the target (window size) its slot was written for
};

// What the render thread answers once the frame is presented (or could not be).
struct FrameDone {
    bool drawn = true;      // false: the swapchain was out of date, nothing was submitted
    bool current = true;    // false: the swapchain must be made again (out of date, suboptimal)
    double recordMs = 0.0;  // recording the chapter's passes
    double submitMs = 0.0;  // the overlay's recording, the submission and the presentation
    std::exception_ptr error;
};

// The one place the threads share, under its mutex: the frame handed over and the answer. The
// render thread is handed a frame only when it has answered the one before (one frame at most
// between them, as the book's single future).
struct Mailbox {
    std::mutex mutex;
    std::condition_variable changed;
    std::optional<FrameJob> job;    // the main thread's, taken by the render thread
    std::optional<FrameDone> done;  // the render thread's, taken by the main thread
    bool quit = false;              // the main thread's: no more frames
};
//< messages

//> render-frame
// The render thread's frame, the book's Render.render from the acquire on: the slot's fence has
// signalled (the main thread waited for it before writing the slot), so the image is acquired, the
// fence reset, the frame recorded, submitted and presented. No GLFW call: presentImage reads no
// window event.
FrameDone renderFrame(common::RenderContext& c, const ThreadedSteps& steps, const FrameJob& job) {
    FrameDone done;
    common::FrameSync& sync = c.frames[job.slot];
    uint32_t imageIndex = 0;
    if (!common::acquireTargetImage(c.target, c.device, sync.imageAvailable, &imageIndex)) {
        done.drawn = done.current = false;
        return done;
    }
    VK_CHECK(vkResetFences(c.device.handle, 1, &sync.inFlight));
    VK_CHECK(vkResetCommandPool(c.device.handle, sync.commandPool, 0));
    VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(sync.commandBuffer, &beginInfo));
    common::timeFrameStart(c.run, sync.commandBuffer, job.slot, job.frame);
    common::FrameCommands commands{
        .cmd = sync.commandBuffer, .slot = job.slot, .frame = job.frame, .imageIndex = imageIndex};
    double recordStart = common::millisecondsSinceStart();
    steps.record(commands);
    double submitStart = common::millisecondsSinceStart();
    done.recordMs = submitStart - recordStart;
    if (c.gui.enabled)
        common::timedPass(c, commands, [&] {
            common::recordGuiPass(commands.cmd, c.guiPass, job.slot, c.target, imageIndex, job.overlay);
        });
    VK_CHECK(vkEndCommandBuffer(sync.commandBuffer));

    VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                               .semaphore = sync.imageAvailable,
                               .stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
    VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                 .semaphore = c.target.renderFinished[imageIndex],
                                 .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    VkCommandBufferSubmitInfo buffer{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                     .commandBuffer = sync.commandBuffer};
    VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                         .waitSemaphoreInfoCount = 1,
                         .pWaitSemaphoreInfos = &wait,
                         .commandBufferInfoCount = 1,
                         .pCommandBufferInfos = &buffer,
                         .signalSemaphoreInfoCount = 1,
                         .pSignalSemaphoreInfos = &signal};
    VK_CHECK(common::vk13.QueueSubmit2(c.device.queue, 1, &submit, sync.inFlight));
    if (job.last) common::screenshotLastFrame(c.run, c.device, c.target, imageIndex);
    done.current = common::presentImage(c.target, c.device, imageIndex);
    done.submitMs = common::millisecondsSinceStart() - submitStart;
    return done;
}
//< render-frame

//> render-thread
// The render thread: a frame at a time, from the mailbox, until the main thread says quit. What
// throws is answered, not thrown: the main thread throws it at the meeting.
void renderThread(common::RenderContext& c, const ThreadedSteps& steps, Mailbox& box) {
    for (;;) {
        FrameJob job;
        {
            std::unique_lock lock(box.mutex);
            box.changed.wait(lock, [&] { return box.job.has_value() || box.quit; });
            if (!box.job) return;
            job = *box.job;
            box.job.reset();
        }
        FrameDone done;
        try {
            done = renderFrame(c, steps, job);
        } catch (...) {
            done.error = std::current_exception();
        }
        {
            std::lock_guard lock(box.mutex);
            box.done = done;
        }
        box.changed.notify_all();
    }
}

// The main thread's side: the render thread started, handed frames, met, and joined (also when
// the main thread throws: it is told to quit once its frame is answered).
class RenderThread {
public:
    RenderThread(common::RenderContext& c, const ThreadedSteps& steps)
        : c_(c), thread_([this, &c, &steps] { renderThread(c, steps, box_); }) {}
    ~RenderThread() {
        {
            std::lock_guard lock(box_.mutex);
            box_.quit = true;
        }
        box_.changed.notify_all();
        thread_.join();
    }
    RenderThread(const RenderThread&) = delete;
    RenderThread& operator=(const RenderThread&) = delete;

    void hand(const FrameJob& job) {
        {
            std::lock_guard lock(box_.mutex);
            box_.job = job;
        }
        pending_ = true;
        box_.changed.notify_all();
    }

    // Waits until the frame handed last is answered (at once when none is out). In a window, the
    // events are read every 50 ms meanwhile, so that a window closed during a long frame ends the
    // run as in the other chapters (common/wnd/target.cpp's waitReadingEvents). Throws what the
    // render thread threw.
    FrameDone meet() {
        if (!pending_) return {};
        std::optional<std::chrono::steady_clock::time_point> closed;
        std::unique_lock lock(box_.mutex);
        while (!box_.changed.wait_for(lock, std::chrono::milliseconds(50),
                                      [&] { return box_.done.has_value(); })) {
            if (!c_.target.window) continue;
            lock.unlock();
            glfwPollEvents();
            if (glfwWindowShouldClose(c_.target.window)) {
                auto now = std::chrono::steady_clock::now();
                if (!closed) closed = now;
                if (now - *closed > std::chrono::milliseconds(common::stopGraceMs()))
                    common::requestStop(true);
            }
            lock.lock();
        }
        FrameDone done = *box_.done;
        box_.done.reset();
        pending_ = false;
        lock.unlock();
        if (done.error) std::rethrow_exception(done.error);
        return done;
    }

private:
    common::RenderContext& c_;
    Mailbox box_;
    bool pending_ = false;  // a frame handed over and not yet answered
    std::thread thread_;    // last: started once the mailbox exists
};
//< render-thread

}  // namespace

bool plantedCameraRace() {
    static const bool race = [] {
        const char* what = std::getenv("VKBOOK_TEST_RACE");
        return what != nullptr && std::strcmp(what, "camera") == 0;
    }();
    return race;
}

//> frame-loop
void runThreadedFrameLoop(common::RenderContext& c, const ThreadedSteps& steps) {
    const common::FrameSteps targetSteps{.remakePipelines = steps.remakePipelines, .resize = steps.resize};
    const uint32_t inFlight = c.framesInFlight;
    {
        RenderThread render(c, steps);
        std::optional<FrameJob> unanswered;  // handed, its answer not yet read
        uint64_t target = 0;                 // counts the times the target was made again
        double lastTime = glfwGetTime();
        auto lastMeeting = std::chrono::steady_clock::now();
        // The window made again (a new size; the render thread waits): frames whose slots were
        // written for the old size are written again before they are handed over.
        auto remakeTarget = [&]() -> bool {
            if (!common::recreateTarget(c, targetSteps)) return false;
            ++target;
            return true;
        };
        bool outOfDate = false;  // the last presentation said the target must be made again
        std::function<bool()> meetRender;
        auto rewriteFor = [&](FrameJob& job) {
            if (job.target == target) return;
            steps.update(job.frame, job.slot, [&] { meetRender(); });
            job.target = target;
        };
        // The answer of the frame handed last. A frame the out-of-date swapchain kept from being
        // drawn is handed again once the target is made again (its slot is written and still its),
        // reading the window's events between tries: a close, or Ctrl+C, ends the run.
        meetRender = [&]() -> bool {
            FrameDone done = render.meet();
            if (!unanswered) return true;
            FrameJob job = *unanswered;
            unanswered.reset();
            while (!done.drawn) {
                if (common::pollTarget(c.target) || common::stopRequested() || !remakeTarget()) return false;
                rewriteFor(job);
                render.hand(job);
                done = render.meet();
            }
            auto now = std::chrono::steady_clock::now();
            common::addCpuSteps(c.run.stats, job.frame, job.mainMs, done.recordMs, done.submitMs);
            common::endFrame(c.run, job.frame,
                             std::chrono::duration<double, std::milli>(now - lastMeeting).count());
            lastMeeting = now;
            if (!done.current) outOfDate = true;  // made again at the meeting, before the next frame
            return true;
        };
        for (uint32_t frame = 0;; ++frame) {
            // A new size seen before this frame's events is taken at its meeting; one its events
            // bring, at the next (the frame is drawn at the size it was begun with, as chapter-19's).
            bool resized = c.target.resized;
            bool last = common::beginFrame(c.run, c.target, frame);  // the window's events
            uint32_t slot = frame % inFlight;
            double inputStart = common::millisecondsSinceStart();
            if (c.target.window) {
                double now = glfwGetTime();
                steps.input(c.target.window, float(now - lastTime), !common::guiWantsKeyboard(c.gui),
                            !common::guiWantsMouse(c.gui));
                lastTime = now;
            }
            steps.advance(frame);
            double inputMs = common::millisecondsSinceStart() - inputStart;
            // The slot is written once the frame that last read it is done: with one frame in
            // flight that frame is the one being recorded, so it is met first.
            if (inFlight == 1 && !meetRender()) break;
            common::FrameSync& sync = c.frames[slot];
            double waitStart = common::millisecondsSinceStart();
            if (c.target
                    .window)  // reading the window's events meanwhile: a close is seen during a long frame
                common::waitForFrame(c.target, c.device, sync.inFlight);
            else
                VK_CHECK(vkWaitForFences(c.device.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX));
            common::addFenceWait(c.run.stats, frame, common::millisecondsSinceStart() - waitStart);
            common::releaseRetiredPipelines(c.device, frame, inFlight);
            common::collectGpuTimes(c.run, c.device, slot);
            double updateStart = common::millisecondsSinceStart();
            FrameJob job{.frame = frame, .slot = slot, .last = last, .target = target};
            steps.update(frame, slot, [&] {
                if (!meetRender()) common::requestStop(false);
            });
            // The main thread's work on the frame (--benchmark's "CPU update"): its waits left out.
            double mainMs = inputMs + common::millisecondsSinceStart() - updateStart;

            // The meeting: the frame before is presented; nothing is recorded until this one is
            // handed over. What changes what the render thread uses happens here.
            if (!meetRender()) break;
            if ((resized || outOfDate) && !remakeTarget()) break;
            outOfDate = false;
            rewriteFor(job);
            if (common::ShaderReload reload = common::pollShaderSources())
                common::reloadShaders(c, targetSteps, reload, frame);
            job.mainMs = mainMs;
            if (c.gui.enabled) {
                job.overlay = common::drawGui(c.gui, c.target, frame, steps.overlay);
                common::updateGuiBuffers(c.device, c.guiPass, slot, job.overlay);
            }
            render.hand(job);
            unanswered = job;
            if (last) break;
        }
        meetRender();
    }  // the render thread joined
    VK_CHECK(vkDeviceWaitIdle(c.device.handle));
}
//< frame-loop
