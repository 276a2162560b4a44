#include "platform/GlContext.h"

#include <glad/gl.h>

#include <cstdio>

namespace gi::platform {

std::string_view providerName(HeadlessProvider provider) {
    return provider == HeadlessProvider::Egl ? "egl" : "osmesa";
}

std::optional<HeadlessProvider> parseProvider(std::string_view name) {
    if (name == "egl") return HeadlessProvider::Egl;
    if (name == "osmesa") return HeadlessProvider::OSMesa;
    return std::nullopt;
}

std::string GlContext::description() const {
    auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

bool loadGlFunctions(ProcLoader getProcAddress, std::string& error) {
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress));
    if (version == 0) {
        error = "could not load OpenGL functions";
        return false;
    }
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 4 || (major == 4 && minor < 5)) {
        error = "OpenGL 4.5 core is required, the context offers " + std::to_string(major) +
                "." + std::to_string(minor);
        return false;
    }
    return true;
}

namespace {

void GLAPIENTRY logDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
        GLsizei length, const GLchar* message, const void*) {
    (void)source;
    (void)length;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    const char* kind = type == GL_DEBUG_TYPE_ERROR ? "error" : "message";
    std::fprintf(stderr, "gl %s %u: %s\n", kind, id, message);
}

} // namespace

void installDebugMessageLog() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(logDebugMessage, nullptr);
}

std::unique_ptr<GlContext> createHeadlessContext(HeadlessProvider preferred, bool allowFallback,
        std::string& error, std::string& notice) {
    auto create = [](HeadlessProvider p, std::string& err) {
        return p == HeadlessProvider::Egl ? createEglContext(err) : createOSMesaContext(err);
    };
    std::string firstError;
    if (auto context = create(preferred, firstError)) return context;
    if (!allowFallback) {
        error = firstError;
        return nullptr;
    }
    const HeadlessProvider other =
            preferred == HeadlessProvider::Egl ? HeadlessProvider::OSMesa : HeadlessProvider::Egl;
    std::string secondError;
    if (auto context = create(other, secondError)) {
        notice = std::string(providerName(preferred)) + " unavailable (" + firstError +
                 "), using " + std::string(providerName(other));
        return context;
    }
    error = std::string(providerName(preferred)) + ": " + firstError + "; " +
            std::string(providerName(other)) + ": " + secondError;
    return nullptr;
}

} // namespace gi::platform
