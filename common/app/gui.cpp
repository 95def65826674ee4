// Dear ImGui: context, input, the timings window.
#include "common/app/gui.hpp"

#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/core/check.hpp"
#include "common/shaders/shader_watch.hpp"

namespace common {
namespace {

constexpr size_t kHistoryFrames = 240;  // the plot: about 4 seconds at 60 frames a second

std::vector<GuiClick> parseClicks(const std::string& text) {
    std::vector<GuiClick> clicks;
    std::istringstream list(text);
    std::string item;
    while (std::getline(list, item, '+')) {
        GuiClick click;
        char comma = 0, at = 0;
        std::istringstream in(item);
        if (!(in >> click.x >> comma >> click.y >> at >> click.frame) || comma != ',' || at != '@' ||
            !(in >> std::ws).eof() || click.x < 0.0f || click.y < 0.0f)
            throw InputError("--gui-click must be X,Y@FRAME[+X,Y@FRAME...] with X, Y >= 0, got '" + text +
                             "'");
        clicks.push_back(click);
    }
    if (clicks.empty()) throw InputError("--gui-click must be X,Y@FRAME[+X,Y@FRAME...], got '" + text + "'");
    return clicks;
}

float parseScale(const std::string& text) {
    char* end = nullptr;
    float scale = std::strtof(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !(scale >= 1.0f && scale <= 4.0f))
        throw InputError("--gui-scale must be a number from 1 to 4, got '" + text + "'");
    return scale;
}

// The scale a window's framebuffer has over its size in points (GLFW's content scale is the
// monitor's setting, which on X11 is not what the framebuffer has).
float windowScale(GLFWwindow* window) {
    int width = 0, height = 0, pixels = 0, rows = 0;
    glfwGetWindowSize(window, &width, &height);
    glfwGetFramebufferSize(window, &pixels, &rows);
    return width > 0 ? std::clamp(float(pixels) / float(width), 1.0f, 4.0f) : 1.0f;
}

}  // namespace

Gui createGui(const Options& options, const Target& target) {
    Gui gui;
    auto clicks = options.values.find("gui-click");
    if (clicks != options.values.end()) gui.clicks = parseClicks(clicks->second);
    auto scale = options.values.find("gui-scale");
    if (scale != options.values.end()) {
        if (target.window)
            throw InputError("--gui-scale is for headless runs; a window has its display's scale");
        gui.scale = parseScale(scale->second);
    }
    gui.enabled = options.switches.count("gui") != 0;
    if (!gui.enabled) return gui;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the working directory: every run starts the same
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    // Dear ImGui's font, rasterised at `scale` pixels a point and drawn at 1/scale: sharp text
    // of the same size in points at any scale.
    if (target.window) gui.scale = windowScale(target.window);
    ImFontConfig font;
    font.SizePixels = 13.0f * gui.scale;  // the default font's own size, 13 pixels at scale 1
    io.Fonts->AddFontDefault(&font);
    io.FontGlobalScale = 1.0f / gui.scale;
    gui.deterministic = target.window == nullptr || options.switches.count("gui-still") != 0;
    if (target.window) gui.glfwBackend = ImGui_ImplGlfw_InitForVulkan(target.window, true);
    return gui;
}

void destroyGui(Gui& gui) {
    if (!gui.enabled) return;
    if (gui.glfwBackend) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    gui = {};
}

namespace {

void beginGui(Gui& gui, const Target& target, uint32_t frame) {
    ImGuiIO& io = ImGui::GetIO();
    if (gui.glfwBackend) {
        ImGui_ImplGlfw_NewFrame();  // window size, time, mouse and keyboard from GLFW
        if (pressedOnce(target.window, gui.toggleKey)) gui.visible = !gui.visible;
    } else {
        // Headless: the image's pixels, `scale` of them a point (ImGui's GLFW backend sets the
        // same two from the window).
        io.DisplaySize =
            ImVec2(float(target.extent.width) / gui.scale, float(target.extent.height) / gui.scale);
        io.DisplayFramebufferScale = ImVec2(gui.scale, gui.scale);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        io.MouseDown[0] = false;
    }
    // A scripted click: the pointer arrives the frame before (ImGui hovers before it presses),
    // the button goes down at the click's frame and up at the next.
    for (const GuiClick& click : gui.clicks)
        if (frame + 1 >= click.frame && frame <= click.frame + 1) {
            io.MousePos = ImVec2(click.x, click.y);
            io.MouseDown[0] = frame == click.frame;
        }
    ImGui::NewFrame();
}

}  // namespace

namespace {

// A shader that failed to reload: its compiler message, in red, until the file is fixed.
void shaderErrorWindow() {
    const std::string& error = shaderReloadError();
    if (error.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + 10.0f, viewport->WorkPos.y + viewport->WorkSize.y - 10.0f),
        ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x - 20.0f, 0.0f), ImGuiCond_Always);
    ImGui::Begin("Shader error (the running shaders are unchanged)", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
    ImGui::End();
}

}  // namespace

ImDrawData* drawGui(Gui& gui, const Target& target, uint32_t frame, const std::function<void()>& widgets) {
    if (!gui.enabled) return nullptr;
    if (frame == 0) {  // the windows' first, invisible frame: they measure themselves
        beginGui(gui, target, frame);
        widgets();
        ImGui::EndFrame();
    }
    beginGui(gui, target, frame);
    widgets();
    shaderErrorWindow();
    ImGui::Render();
    return gui.visible ? ImGui::GetDrawData() : nullptr;
}

bool guiCombo(const char* label, const std::vector<std::string>& names, int* index) {
    bool changed = false;
    ImGui::SetNextItemWidth(140.0f);
    if (ImGui::BeginCombo(label, names[size_t(*index)].c_str())) {
        for (int i = 0; i < int(names.size()); ++i)
            if (ImGui::Selectable(names[size_t(i)].c_str(), i == *index)) changed = *index != i, *index = i;
        ImGui::EndCombo();
    }
    return changed;
}

bool guiWantsMouse(const Gui& gui) {
    return gui.enabled && gui.visible && ImGui::GetIO().WantCaptureMouse;
}

bool guiWantsKeyboard(const Gui& gui) {
    return gui.enabled && gui.visible && ImGui::GetIO().WantCaptureKeyboard;
}

//> gui-timings
bool guiTimingsWindow(Gui& gui, const RunControl& run, const std::vector<std::string>& views, int* view,
                      const std::vector<std::string>& keys) {
    const GpuTimer& timer = run.gpuTimer;
    if (!timer.latest.empty() && timer.latestFrame != gui.plottedFrame) {
        gui.plottedFrame = timer.latestFrame;
        gui.frameHistory.push_back(float(timer.latest.front()));
        if (gui.frameHistory.size() > kHistoryFrames) gui.frameHistory.erase(gui.frameHistory.begin());
    }
    // A fixed place and size rule: the same pixels every run (tests click on it).
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
    ImGui::Begin("Frame", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    // Headless, the image must not depend on the timings: placeholders instead.
    auto milliseconds = [&](size_t index) {
        char text[32];
        if (gui.deterministic || index >= timer.latest.size()) return std::string("--.--- ms");
        std::snprintf(text, sizeof text, "%.3f ms", timer.latest[index]);
        return std::string(text);
    };
    char cpu[32] = "--.--- ms";
    if (!gui.deterministic && run.lastCpuMs > 0.0) std::snprintf(cpu, sizeof cpu, "%.3f ms", run.lastCpuMs);
    ImGui::Text("GPU frame  %s   CPU frame %s", milliseconds(0).c_str(), cpu);
    for (size_t pass = 0; pass < timer.passes.size(); ++pass)
        ImGui::Text("  %-8s %s", timer.passes[pass].c_str(), milliseconds(pass + 1).c_str());
    std::vector<float> plotted =
        gui.deterministic ? std::vector<float>(kHistoryFrames, 0.0f) : gui.frameHistory;
    float highest =
        plotted.empty() ? 1.0f : std::max(*std::max_element(plotted.begin(), plotted.end()), 1e-3f);
    ImGui::PlotLines("##frames", plotted.data(), int(plotted.size()), 0, "GPU frame, last seconds", 0.0f,
                     highest * 1.2f, ImVec2(240.0f, 60.0f));
    bool changed = views.size() > 1 && guiCombo("view", views, view);
    ImGui::Checkbox("help", &gui.help);
    ImGui::End();
    if (gui.help) {
        ImGui::SetNextWindowPos(
            ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::Begin("Help", &gui.help, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
        ImGui::TextUnformatted("Keys (while the overlay does not have the keyboard):");
        ImGui::TextUnformatted("  W/S/A/D, Up/Down  move the camera; right-drag looks around");
        for (const std::string& key : keys) ImGui::Text("  %s", key.c_str());
        ImGui::TextUnformatted("  F1  hides and shows this overlay");
        ImGui::Separator();
        ImGui::TextUnformatted("The frame's passes, in order, each timed by GPU timestamps:");
        for (const std::string& pass : timer.passes) ImGui::BulletText("%s", pass.c_str());
        ImGui::Separator();
        ImGui::TextWrapped(
            "The GUI pass draws this overlay: Dear ImGui builds its windows as lists of textured, coloured "
            "triangles; the pass copies them into a vertex and an index buffer of the frame, and draws each "
            "list's commands over the presented image, clipped by their scissor rectangles, blended by "
            "their alpha, with the font atlas as the one texture.");
        ImGui::End();
    }
    return changed;
}
//< gui-timings

}  // namespace common
