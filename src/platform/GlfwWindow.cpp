#include "platform/GlfwWindow.h"

#include <glad/gl.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <utility>

namespace gi::platform {
namespace {

// GLFW reports errors through one process-wide callback; the last message is kept here so
// creation failures can say what GLFW said.
std::string sLastGlfwError;

void recordGlfwError(int code, const char* description) {
    (void)code;
    sLastGlfwError = description ? description : "unknown GLFW error";
}

bool environmentSet(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

// GLFW's X11 backend says "The DISPLAY environment variable is missing" or "Failed to open
// display"; its Wayland backend "Failed to connect to display".
bool saysNoDisplay(const std::string& message) {
    std::string lower = message;
    std::transform(lower.begin(), lower.end(), lower.begin(),
            [](unsigned char c) { return char(std::tolower(c)); });
    return lower.find("display") != std::string::npos;
}

struct NamedKey {
    int key;
    const char* name;
};

constexpr std::array kNamedKeys = {
    NamedKey{GLFW_KEY_ESCAPE, "ESCAPE"}, NamedKey{GLFW_KEY_SPACE, "SPACE"},
    NamedKey{GLFW_KEY_ENTER, "ENTER"}, NamedKey{GLFW_KEY_TAB, "TAB"},
    NamedKey{GLFW_KEY_BACKSPACE, "BACKSPACE"}, NamedKey{GLFW_KEY_UP, "UP"},
    NamedKey{GLFW_KEY_DOWN, "DOWN"}, NamedKey{GLFW_KEY_LEFT, "LEFT"},
    NamedKey{GLFW_KEY_RIGHT, "RIGHT"}, NamedKey{GLFW_KEY_MINUS, "-"},
    NamedKey{GLFW_KEY_EQUAL, "="}, NamedKey{GLFW_KEY_HOME, "HOME"},
};

} // namespace

std::unique_ptr<GlfwWindow> GlfwWindow::create(const WindowOptions& options,
        WindowFailure& failure, std::string& error) {
    failure = WindowFailure::Other;
    if (!environmentSet("DISPLAY") && !environmentSet("WAYLAND_DISPLAY")) {
        failure = WindowFailure::NoDisplay;
        error = "no display: DISPLAY and WAYLAND_DISPLAY are unset";
        return nullptr;
    }
    sLastGlfwError.clear();
    glfwSetErrorCallback(recordGlfwError);
    if (!glfwInit()) {
        if (saysNoDisplay(sLastGlfwError)) failure = WindowFailure::NoDisplay;
        error = (failure == WindowFailure::NoDisplay ? "no display: " : "GLFW init failed: ") +
                sLastGlfwError;
        return nullptr;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
#ifndef NDEBUG
    const bool debugContext = true;
#else
    const bool debugContext = options.debugContext;
#endif
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugContext ? GLFW_TRUE : GLFW_FALSE);

    GLFWwindow* raw = glfwCreateWindow(std::max(options.width, 1), std::max(options.height, 1),
            options.title.c_str(), nullptr, nullptr);
    if (!raw) {
        error = "could not open an OpenGL 4.5 core window: " + sLastGlfwError;
        glfwTerminate();
        return nullptr;
    }
    std::unique_ptr<GlfwWindow> window(new GlfwWindow(raw));
    glfwMakeContextCurrent(raw);
    glfwSetWindowUserPointer(raw, window.get());
    glfwSetKeyCallback(raw, onKey);
    glfwSetScrollCallback(raw, onScroll);
    glfwSetDropCallback(raw, onDrop);
    if (!loadGlFunctions(reinterpret_cast<ProcLoader>(glfwGetProcAddress), error)) return nullptr;
    if (debugContext) installDebugMessageLog();
    window->setVsync(true);
    failure = WindowFailure::None;
    return window;
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

void GlfwWindow::pollEvents() { glfwPollEvents(); }

void GlfwWindow::waitEvents(double seconds) { glfwWaitEventsTimeout(seconds); }

void GlfwWindow::swapBuffers() { glfwSwapBuffers(mWindow); }

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(mWindow) != 0; }

void GlfwWindow::requestClose() { glfwSetWindowShouldClose(mWindow, GLFW_TRUE); }

void GlfwWindow::setVsync(bool on) {
    glfwSwapInterval(on ? 1 : 0);
    mVsync = on;
}

glm::ivec2 GlfwWindow::framebufferSize() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(mWindow, &size.x, &size.y);
    return size;
}

std::vector<int> GlfwWindow::takeKeyPresses() { return std::exchange(mKeyPresses, {}); }

bool GlfwWindow::keyDown(int glfwKey) const { return glfwGetKey(mWindow, glfwKey) == GLFW_PRESS; }

bool GlfwWindow::mouseButtonDown(int glfwButton) const {
    return glfwGetMouseButton(mWindow, glfwButton) == GLFW_PRESS;
}

glm::dvec2 GlfwWindow::cursorPosition() const {
    glm::dvec2 position(0.0);
    glfwGetCursorPos(mWindow, &position.x, &position.y);
    return position;
}

double GlfwWindow::takeScroll() { return std::exchange(mScroll, 0.0); }

std::vector<std::string> GlfwWindow::takeDroppedPaths() {
    return std::exchange(mDroppedPaths, {});
}

void GlfwWindow::setTitle(const std::string& title) { glfwSetWindowTitle(mWindow, title.c_str()); }

void GlfwWindow::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
    if (self && action == GLFW_PRESS && key != GLFW_KEY_UNKNOWN) self->mKeyPresses.push_back(key);
}

void GlfwWindow::onScroll(GLFWwindow* window, double dx, double dy) {
    (void)dx;
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
    if (self) self->mScroll += dy;
}

void GlfwWindow::onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
    if (!self) return;
    for (int i = 0; i < count; ++i) {
        if (paths[i]) self->mDroppedPaths.emplace_back(paths[i]);
    }
}

std::string keyName(int glfwKey) {
    if (glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z) {
        return std::string(1, char('A' + (glfwKey - GLFW_KEY_A)));
    }
    if (glfwKey >= GLFW_KEY_0 && glfwKey <= GLFW_KEY_9) {
        return std::string(1, char('0' + (glfwKey - GLFW_KEY_0)));
    }
    if (glfwKey >= GLFW_KEY_F1 && glfwKey <= GLFW_KEY_F25) {
        std::string name = "F";
        name += std::to_string(glfwKey - GLFW_KEY_F1 + 1);
        return name;
    }
    for (const NamedKey& named : kNamedKeys) {
        if (named.key == glfwKey) return named.name;
    }
    return {};
}

int keyFromName(const std::string& name) {
    std::string upper = name;
    std::transform(upper.begin(), upper.end(), upper.begin(),
            [](unsigned char c) { return char(std::toupper(c)); });
    if (upper == "ESC") upper = "ESCAPE";
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
        if (!upper.empty() && keyName(key) == upper) return key;
    }
    return -1;
}

} // namespace gi::platform
