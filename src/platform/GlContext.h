// OpenGL context providers behind one interface: a GLFW window for the viewer, and two
// headless providers (EGL surfaceless, OSMesa) for `voxatlas render`, tests and benches.
// Every provider loads GL entry points through the one glad 2 loader with its own
// GetProcAddress, so the same GL code runs on all three (under OSMesa, functions resolved
// through libGL would return nothing).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace gi::platform {

enum class HeadlessProvider { Egl, OSMesa };

[[nodiscard]] std::string_view providerName(HeadlessProvider provider);
[[nodiscard]] std::optional<HeadlessProvider> parseProvider(std::string_view name);

// A current GL 4.5 core context. Headless contexts have no usable default framebuffer:
// everything renders into framebuffer objects.
class GlContext {
public:
    virtual ~GlContext() = default;
    // "egl", "osmesa" or "glfw".
    virtual std::string_view provider() const = 0;
    // GL_RENDERER and GL_VERSION of the created context, for logs and reports.
    std::string description() const;
};

[[nodiscard]] std::unique_ptr<GlContext> createEglContext(std::string& error);
[[nodiscard]] std::unique_ptr<GlContext> createOSMesaContext(std::string& error);

// Creates the preferred provider; if that fails and a fallback is allowed, tries the other
// one and writes a one-line notice explaining the fallback.
[[nodiscard]] std::unique_ptr<GlContext> createHeadlessContext(HeadlessProvider preferred,
        bool allowFallback, std::string& error, std::string& notice);

// Loads every GL 4.5 function through `getProcAddress` and checks the context's version.
using ProcLoader = void (*(*)(const char*))();
[[nodiscard]] bool loadGlFunctions(ProcLoader getProcAddress, std::string& error);

// Routes KHR_debug messages to stderr (synchronous, so a message names the call that caused
// it). Used for debug builds and by `--set gl.debug=1`.
void installDebugMessageLog();

} // namespace gi::platform
