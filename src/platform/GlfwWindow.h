// The viewer's GL context provider: a resizable GLFW window with a GL 4.5 core,
// forward-compatible context (a KHR_debug context in debug builds or with gl.debug=1), its
// entry points loaded through the project's glad loader with glfwGetProcAddress. Key presses
// and files dropped on the window arrive as queues the viewer drains once per frame; held
// keys, mouse buttons, the cursor and the scroll wheel are polled, so the caller decides what
// input means. Creation failures are one clean line, and a missing display is told apart from
// other failures so the viewer can fall back to a headless screenshot.
#pragma once

#include "platform/GlContext.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace gi::platform {

struct WindowOptions {
    std::string title = "voxatlas";
    int width = 1280, height = 720;   // window size in screen coordinates
    bool debugContext = false;        // request a KHR_debug context even in release builds
};

enum class WindowFailure { None, NoDisplay, Other };

class GlfwWindow final : public GlContext {
public:
    // Opens the window and makes its context current. On failure returns null, sets `failure`
    // and writes one line to `error` ("no display: ..." when there is no display to open).
    [[nodiscard]] static std::unique_ptr<GlfwWindow> create(const WindowOptions& options,
            WindowFailure& failure, std::string& error);

    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    std::string_view provider() const override { return "glfw"; }

    void pollEvents();
    // Sleeps until an event arrives or `seconds` pass (while minimised: nothing to draw).
    void waitEvents(double seconds);
    void swapBuffers();
    [[nodiscard]] bool shouldClose() const;
    void requestClose();
    void setVsync(bool on);
    [[nodiscard]] bool vsync() const { return mVsync; }

    // Drawable size in pixels (differs from the window size on high-DPI screens).
    [[nodiscard]] glm::ivec2 framebufferSize() const;

    // GLFW key codes pressed since the last call (repeats excluded), in order.
    [[nodiscard]] std::vector<int> takeKeyPresses();
    [[nodiscard]] bool keyDown(int glfwKey) const;
    [[nodiscard]] bool mouseButtonDown(int glfwButton) const;
    // Cursor position in window coordinates, y down.
    [[nodiscard]] glm::dvec2 cursorPosition() const;
    // Vertical scroll wheel steps since the last call.
    [[nodiscard]] double takeScroll();
    // Paths of the files dropped on the window since the last call, in order.
    [[nodiscard]] std::vector<std::string> takeDroppedPaths();
    void setTitle(const std::string& title);

    // For libraries that talk to GLFW directly (the ImGui backend).
    [[nodiscard]] GLFWwindow* handle() const { return mWindow; }

private:
    explicit GlfwWindow(GLFWwindow* window) : mWindow(window) {}
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onDrop(GLFWwindow* window, int count, const char** paths);

    GLFWwindow* mWindow = nullptr;
    std::vector<int> mKeyPresses;
    std::vector<std::string> mDroppedPaths;
    double mScroll = 0.0;
    bool mVsync = false;
};

// Hotkey names shared by the key callback and `view --keys`: "A".."Z", "0".."9", "F1".."F25",
// "ESCAPE", "SPACE", "ENTER", "TAB", "BACKSPACE", "UP", "DOWN", "LEFT", "RIGHT". Empty for
// keys without a name here.
[[nodiscard]] std::string keyName(int glfwKey);
// The GLFW key code for a name (case-insensitive), or -1.
[[nodiscard]] int keyFromName(const std::string& name);

} // namespace gi::platform
