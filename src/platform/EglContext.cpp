// EGL headless provider: a GL 4.5 core context without any surface, on Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless), or on the first EGL device when that is absent.
#include "platform/GlContext.h"

#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace gi::platform {
namespace {

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context) : mDisplay(display), mContext(context) {}
    ~EglContext() override {
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(mDisplay, mContext);
        eglTerminate(mDisplay);
    }
    std::string_view provider() const override { return "egl"; }

private:
    EGLDisplay mDisplay;
    EGLContext mContext;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name)) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

EGLDisplay openDisplay(std::string& error) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        error = "EGL lacks eglGetPlatformDisplayEXT";
        return EGL_NO_DISPLAY;
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display =
                getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY) return display;
    }
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
                eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT device = nullptr;
        EGLint count = 0;
        if (queryDevices && queryDevices(1, &device, &count) && count > 0) {
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (display != EGL_NO_DISPLAY) return display;
        }
    }
    error = "no EGL surfaceless or device platform";
    return EGL_NO_DISPLAY;
}

} // namespace

std::unique_ptr<GlContext> createEglContext(std::string& error) {
    EGLDisplay display = openDisplay(error);
    if (display == EGL_NO_DISPLAY) return nullptr;
    if (!eglInitialize(display, nullptr, nullptr)) {
        error = "eglInitialize failed";
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        error = "EGL has no desktop OpenGL API";
        eglTerminate(display);
        return nullptr;
    }
    // EGL_KHR_no_config_context lets a surfaceless context exist without an EGLConfig.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0) {
            error = "no EGL config renders desktop OpenGL";
            eglTerminate(display);
            return nullptr;
        }
    }
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) {
        error = "EGL could not create an OpenGL 4.5 core context";
        eglTerminate(display);
        return nullptr;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        error = "eglMakeCurrent without a surface failed";
        eglDestroyContext(display, context);
        eglTerminate(display);
        return nullptr;
    }
    auto result = std::make_unique<EglContext>(display, context);
    if (!loadGlFunctions(reinterpret_cast<ProcLoader>(eglGetProcAddress), error)) return nullptr;
    return result;
}

} // namespace gi::platform
