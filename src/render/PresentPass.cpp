#include "render/PresentPass.h"
#include "core/Colour.h"

#include "gl/Shared.h"
#include "scene/Scene.h"

#include <array>
#include <cstdint>
#include <vector>

namespace gi::render {

bool PresentPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"render/present",
            {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                    {GL_FRAGMENT_SHADER, "render/present.frag"}},
            {}}, error);
    mEmpty = gl::createVertexArray("render/present/empty");
    mBilinear = gl::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
            "render/present/bilinear");
    return bool(mProgram);
}

void PresentPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "render/present");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, out.framebufferSize.x, out.framebufferSize.y);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    glUseProgram(mProgram.id());
    glProgramUniform1f(mProgram.id(), LOC_PRESENT_SCALE, in.scale);
    glProgramUniform1f(mProgram.id(), LOC_PRESENT_EXPOSURE, in.exposure);
    glProgramUniform1i(mProgram.id(), LOC_PRESENT_CURVE,
            in.curve == core::ToneCurve::Filmic ? TONE_CURVE_FILMIC : TONE_CURVE_NONE);
    glBindTextureUnit(BIND_TEX_PRESENT_SOURCE, in.radiance.id());
    glBindSampler(BIND_TEX_PRESENT_SOURCE, mBilinear.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(BIND_TEX_PRESENT_SOURCE, 0);
    glBindTextureUnit(BIND_TEX_PRESENT_SOURCE, 0);
    glUseProgram(0);
}

core::Image PresentPass::readDefaultFramebuffer(glm::ivec2 size) {
    std::vector<std::uint8_t> rgba(std::size_t(size.x) * std::size_t(size.y) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glNamedFramebufferReadBuffer(0, GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadnPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()),
            rgba.data());
    std::array<float, 256> decode{};
    for (int i = 0; i < 256; ++i) decode[std::size_t(i)] = core::srgbToLinear(float(i) / 255.0f);
    core::Image image(size.x, size.y);
    // GL rows run bottom to top; images run top to bottom.
    for (int y = 0; y < size.y; ++y) {
        const std::uint8_t* row =
                rgba.data() + std::size_t(size.y - 1 - y) * std::size_t(size.x) * 4;
        for (int x = 0; x < size.x; ++x) {
            const std::uint8_t* p = row + std::size_t(x) * 4;
            image.set(x, y, {decode[p[0]], decode[p[1]], decode[p[2]]});
        }
    }
    return image;
}

} // namespace gi::render
