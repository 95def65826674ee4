// Dear ImGui for chapters 14 and 15: the overlay's widgets and input (--gui). The book draws a GUI
// with Dear ImGui in every chapter from its GUI chapter on, its GuiRender turning ImGui's draw
// lists into Vulkan draws; that pass is common/passes/gui_pass.cpp. This module is the ImGui side: the
// context, GLFW input (Dear ImGui's own GLFW backend, for input only), F1, the timings window both chapters
// show, and a headless mode that draws the same overlay deterministically (for golden images).
#pragma once

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/app/cli.hpp"
#include "common/app/run_control.hpp"
#include "common/scene/camera.hpp"
#include "common/wnd/target.hpp"

namespace common {

// A scripted left click (--gui-click X,Y@FRAME): the pointer at (X, Y) in window points from the frame
// before FRAME, the button down at FRAME and up at the next. A testing aid, like --resize.
struct GuiClick {
    float x = 0.0f, y = 0.0f;
    uint32_t frame = 0;
};

struct Gui {
    bool enabled = false;        // --gui
    bool visible = true;         // F1 hides and shows the overlay
    bool deterministic = false;  // headless or --gui-still: timings as placeholders
    bool glfwBackend = false;    // Dear ImGui's GLFW backend feeds input (a window)
    // Pixels per window point: 2 on a HiDPI display (macOS Retina, Wayland at scale 2), --gui-scale
    // headless. ImGui lays out in points; the font is rasterised at this many pixels a point.
    float scale = 1.0f;
    KeyPress toggleKey{GLFW_KEY_F1};
    std::vector<GuiClick> clicks;
    bool help = false;                // the help window: keys and passes
    std::vector<float> frameHistory;  // the GPU frame time of the last frames, for the plot
    uint32_t plottedFrame = UINT32_MAX;
};

// The chapter-specific options every GUI chapter adds to its ChapterInfo.
inline const std::pair<std::string, std::string> kGuiSwitch{
    "gui", "draw the Dear ImGui overlay (F1 hides and shows it); headless, deterministically"};
inline const std::pair<std::string, std::string> kGuiStillSwitch{
    "gui-still", "testing aid: the overlay shows placeholders, not timings, in a window too"};
inline const Choice kGuiClickChoice{"gui-click",
                                    {},
                                    "testing aid: scripted left clicks of the overlay, "
                                    "X,Y@FRAME[+X,Y@FRAME...] (window points, frames at least 3 apart)"};
inline const Choice kGuiScaleChoice{"gui-scale",
                                    {},
                                    "testing aid, headless: the overlay's pixels per point, 1..4 (a "
                                    "HiDPI display's scale; in a window the display's own is used)"};

// The context (nothing when --gui is not given). Throws InputError for a bad --gui-click or
// --gui-scale.
Gui createGui(const Options& options, const Target& target);
void destroyGui(Gui& gui);
// One ImGui frame: input (F1 toggles the overlay), `widgets` (the chapter's ImGui calls), and
// the draw data the GUI pass draws, or nullptr when there is no overlay or it is hidden. Call after
// common::beginFrame. ImGui sizes a new window on its first frame and shows it from the second, so
// the first frame runs the widgets twice: a one-frame headless image has the overlay too.
ImDrawData* drawGui(Gui& gui, const Target& target, uint32_t frame, const std::function<void()>& widgets);
// A drop-down list of `names` (140 pixels wide) choosing `*index`; true when the choice changed.
bool guiCombo(const char* label, const std::vector<std::string>& names, int* index);
// Whether the overlay takes the mouse or the keyboard this frame: the camera and the chapters'
// keys then leave them alone.
bool guiWantsMouse(const Gui& gui);
bool guiWantsKeyboard(const Gui& gui);
// The overlay's first window, in both chapters: the CPU frame time and the GPU time of the frame
// and of each pass as numbers, the GPU
// frame time of the last seconds as a plot, the --view selector, and a "help" box that opens a
// window of text: the keys (`keys`, one per line) and the passes. Returns true when the view changed.
bool guiTimingsWindow(Gui& gui, const RunControl& run, const std::vector<std::string>& views, int* view,
                      const std::vector<std::string>& keys);

}  // namespace common
