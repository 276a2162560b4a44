// OSMesa headless provider: Mesa's off-screen GL 4.5 core context (OSMesaCreateContextAttribs).
// OSMesa needs a colour buffer to make a context current; a 1x1 buffer serves, since all
// rendering goes to framebuffer objects. Every GL function comes from OSMesaGetProcAddress.
#include "platform/GlContext.h"

#include <glad/gl.h>

#include <GL/osmesa.h>

#include <array>

namespace gi::platform {
namespace {

class OSMesaGlContext final : public GlContext {
public:
    explicit OSMesaGlContext(OSMesaContext context) : mContext(context) {}
    ~OSMesaGlContext() override { OSMesaDestroyContext(mContext); }
    std::string_view provider() const override { return "osmesa"; }
    bool makeCurrent() {
        return OSMesaMakeCurrent(mContext, mPixel.data(), GL_UNSIGNED_BYTE, 1, 1) == GL_TRUE;
    }

private:
    OSMesaContext mContext;
    std::array<unsigned char, 4> mPixel{};
};

} // namespace

std::unique_ptr<GlContext> createOSMesaContext(std::string& error) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE,
            OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5,
            0};
    OSMesaContext raw = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!raw) {
        error = "OSMesa could not create an OpenGL 4.5 core context";
        return nullptr;
    }
    auto context = std::make_unique<OSMesaGlContext>(raw);
    if (!context->makeCurrent()) {
        error = "OSMesaMakeCurrent failed";
        return nullptr;
    }
    if (!loadGlFunctions(reinterpret_cast<ProcLoader>(OSMesaGetProcAddress), error)) {
        return nullptr;
    }
    return context;
}

} // namespace gi::platform
