// The frame loop of chapter 15 on, written once: the book's Engine (the loop: input, update,
// render) and the skeleton of its Render.render (wait for the frame's fence, acquire, record,
// submit, present, resize). Chapters 06, 10 and 14 write the loop out, where it is the lesson;
// from chapter 15 a chapter is its passes and its scene, and gives the loop the steps below.
//
// What a chapter from 15 on makes first and destroys last is a RenderContext (the book's VkCtx
// with Render's command buffers, fences, pipeline cache and GUI): openRenderContext makes it in
// the book's order, closeRenderContext destroys it in reverse.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/app/cli.hpp"
#include "common/app/gui.hpp"
#include "common/app/light_controls.hpp"
#include "common/app/run_control.hpp"
#include "common/passes/gui_pass.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"
#include "common/wnd/target.hpp"

namespace common {

struct RenderContext {
    Target target;  // the window (or headless images) and its swapchain
    Instance instance;
    Device device;
    std::vector<FrameSync> frames;  // per frame in flight: command pool and buffer, fence, semaphore
    uint32_t framesInFlight = 0;
    PipelineCache pipelineCache;
    Gui gui;          // --gui: Dear ImGui's context and input (common/app/gui.cpp)
    GuiPass guiPass;  // --gui: the overlay drawn last, as the book's GuiRender
    RunControl run;   // --frames, --resize, --benchmark (each pass timed), --screenshot
};

// The window or headless target titled `title`, the instance and device (`features`: what the
// chapter asks for), the target's images, the frames in flight, the pipeline cache named
// `chapter`, and the GUI when --gui asks for it.
RenderContext openRenderContext(const Options& options, const std::string& chapter, const std::string& title,
                                const DeviceFeatures& features);
// Once the chapter's passes are made: `passes` names them in recording order (their benchmark
// rows and debug labels); the GUI pass follows them when there is one.
void startRunControl(RenderContext& context, const Options& options, std::vector<std::string> passes);
// After the chapter destroyed its passes and scene: everything openRenderContext made, in reverse.
void closeRenderContext(RenderContext& context);

// What a frame records into: its command buffer, its slot among the frames in flight, its number,
// the image it presents, and the next pass to time.
struct FrameCommands {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    uint32_t slot = 0;
    uint32_t frame = 0;
    uint32_t imageIndex = 0;
    uint32_t pass = 0;  // timedPass's count
};

// One of the frame's passes, `record` recording it between a debug label and a GPU timestamp
// (--benchmark, --gui): the passes in the order startRunControl named them.
void timedPass(const RenderContext& context, FrameCommands& frame, const std::function<void()>& record);

// The chapter's part of a frame, called in this order.
struct FrameSteps {
    // Shaders were edited (common/shaders/shader_watch.hpp): each pass whose shaders changed puts
    // its new pipelines in `swap`, or throws. The loop swaps them all in, or none.
    std::function<void(const ShaderReload& reload, PipelineSwap& swap)> remakePipelines;
    // --gui: the chapter's Dear ImGui windows for this frame.
    std::function<void()> overlay;
    // In a window: the keys and mouse, `seconds` after the last frame's; `keys` and `mouse` are
    // false while the overlay has them.
    std::function<void(GLFWwindow* window, float seconds, bool keys, bool mouse)> input;
    // Once the frame's slot is free: what the frame draws (the book's update, and its passes'
    // uniforms).
    std::function<void(uint32_t frame, uint32_t slot)> update;
    // The chapter's passes (timedPass each); the loop then records the GUI pass. With `present`
    // given, `record` holds the passes that do not write the presented image and `present` those
    // that do.
    std::function<void(FrameCommands& frame)> record;
    std::function<void(FrameCommands& frame)> present;
    // The lab's --acquire late: `record`'s passes submitted before the image is acquired,
    // `present`'s (and the GUI's) after it, into a second command buffer, alone waiting for it.
    bool acquireLate = false;
    // The window changed size (the swapchain and its images are made again first): every image of
    // the window's size, and what writes the presented image (the format may change too).
    std::function<void()> resize;
};

// Frames until the last (--frames, the window closed, Ctrl+C), then vkDeviceWaitIdle.
void runFrameLoop(RenderContext& context, const FrameSteps& steps);

// Two steps of the loop, for a chapter that writes its own (chapter-20's, on two threads); the
// caller makes sure that no frame is being recorded meanwhile.
// Live reload: `steps.remakePipelines` (and the GUI's) for the changed shaders, swapped in at frame
// `frame`, or none and the error shown.
void reloadShaders(RenderContext& context, const FrameSteps& steps, const ShaderReload& reload,
                   uint32_t frame);
// The window changed size: the device waited for, the swapchain and `steps.resize`. False when the
// window is gone.
bool recreateTarget(RenderContext& context, const FrameSteps& steps);

// After the loop, what every chapter from 15 on reports: where the camera went (when it moved),
// --benchmark's report with `info` (common::benchmarkInfo and the chapter's rows), the GUI
// buffers' growth, where the lights went (when they moved).
void reportChapterRun(const ChapterInfo& chapter, RenderContext& context,
                      const std::vector<std::pair<std::string, std::string>>& info, const Scene& scene,
                      const Camera& camera, const LightControls& lights);

}  // namespace common
