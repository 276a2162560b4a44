// The viewer's overlay (Dear ImGui 1.86, Debian's GLFW + OpenGL3 backends): frame time with
// its recent history, a table of per-pass GPU and CPU milliseconds from the GpuProfiler,
// allocated GPU memory per resource, the current mode, output and camera, the scene's size,
// the internal render resolution against the frame budget, one-line notices, shader reload
// errors and the error of a dropped file that did not open, a few Settings widgets, and the
// hotkey help (H). Everything ImGui lives in Ui.cpp; the viewer only hands over a UiFrame.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "core/Settings.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace gi::platform {
class GlfwWindow;
}

namespace gi::app {

// One line of the hotkey help: the key(s) and what they do.
struct HotkeyHelp {
    std::string keys;
    std::string action;
};

// What the overlay shows for one frame.
struct UiFrame {
    double frameMs = 0.0;                          // wall time of the last frame, ms
    std::vector<gl::PassTiming> timings;           // GpuProfiler::timings()
    std::vector<gl::MemoryItem> memory;            // FrameRenderer::memory()
    std::string mode;                              // "direct", ...
    std::string giStatus;                          // GiTechnique::status(), may be empty
    std::string shadowStatus;                      // render::describeShadowMethod
    std::string plan;                              // render::describePlan() of the renderer
    std::string output;                            // "final", "direct", "indirect"
    std::string exposure;                          // ViewerExposure::label()
    std::string camera;                            // e.g. "1/2 Camera" or "free"
    std::size_t triangles = 0;
    glm::ivec2 framebufferSize{0};                 // pixels
    glm::ivec2 renderSize{0};                      // internal render size (frame budget)
    float budgetMs = 0.0f;                         // view.frame_budget_ms, 0 = off
    bool reduced = false;                          // rendered below full size: camera moving
    bool vsync = false;
    float speed = 0.0f;                            // fly speed, m/s
    std::string notice;                            // one line, empty for none
    std::string shaderErrors;                      // last failed reload, empty when fine
    std::string openError;                         // last dropped file that failed to open
};

class Ui {
public:
    Ui() = default;
    ~Ui();
    Ui(const Ui&) = delete;
    Ui& operator=(const Ui&) = delete;

    // Creates the ImGui context and its GLFW and OpenGL3 backends for `window`; call after the
    // window's own input callbacks are installed (the backend chains to them).
    bool init(platform::GlfwWindow& window, std::string& error);

    // Builds and draws the overlay into the default framebuffer. Returns true when a widget
    // changed `settings`.
    bool draw(const UiFrame& frame, Settings& settings, gl::GpuProfiler& profiler);

    // The overlay wants the mouse (hovering or dragging a widget) or the keyboard (text input):
    // the viewer then leaves that input alone.
    [[nodiscard]] bool wantsMouse() const;
    [[nodiscard]] bool wantsKeyboard() const;

    // The hotkey help shown with H (the viewer's own table, so help and handler agree).
    void setHotkeys(std::vector<HotkeyHelp> hotkeys) { mHotkeys = std::move(hotkeys); }
    void toggleHelp() { mShowHelp = !mShowHelp; }
    bool helpVisible() const { return mShowHelp; }

private:
    static constexpr int kHistory = 120;   // frames in the frame-time plot

    // The hotkey table in the top-right corner.
    void helpWindow();

    bool mInitialised = false;
    bool mShowHelp = false;
    std::vector<HotkeyHelp> mHotkeys;
    std::vector<float> mFrameMs = std::vector<float>(kHistory, 0.0f);
    int mHistoryNext = 0;
};

} // namespace gi::app
