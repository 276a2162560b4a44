// Shows a frame in the viewer's window: the FrameRenderer's linear-radiance texture drawn over
// the whole default framebuffer with one full-screen triangle, times the exposure, through the
// tone curve and sRGB-encoded in the shader (core/ToneMap.h's mapping, in
// shaders/common/tonemap.glsl), sampled bilinearly when the render size differs from the
// window's (render.supersample > 1).
// Inputs : radiance, RGBA32F linear radiance W/(m^2 sr) divided by `scale`, any size.
// Outputs: the default framebuffer (0), RGBA8 sRGB-encoded values, alpha 1.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "core/Image.h"
#include "core/ToneMap.h"

#include <glm/glm.hpp>

#include <string>

namespace gi::render {

class PresentPass {
public:
    struct Inputs {
        const gl::Texture& radiance;    // RGBA32F, linear radiance / scale
        float scale = 1.0f;             // FrameRenderer::radianceScale()
        float exposure = 1.0f;          // display multiplier, 2^EV
        core::ToneCurve curve = core::ToneCurve::None;
    };
    struct Outputs {
        glm::ivec2 framebufferSize;     // pixels of the default framebuffer
    };

    // Returns false with the shader error if the program does not build.
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

    // What the window shows now (the back buffer, before the swap), decoded from sRGB back to
    // linear so the PNG writer reproduces the same 8-bit values. For overlay screenshots.
    [[nodiscard]] static core::Image readDefaultFramebuffer(glm::ivec2 size);

private:
    gl::ProgramRef mProgram;
    gl::VertexArray mEmpty;     // core profile needs a bound VAO even without attributes
    gl::Sampler mBilinear;
};

} // namespace gi::render
