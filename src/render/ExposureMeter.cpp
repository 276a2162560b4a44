#include "render/ExposureMeter.h"

#include "core/Image.h"
#include "core/ToneMap.h"
#include "gl/RenderTarget.h"

#include <cstdio>
#include <string>
#include <vector>

namespace gi::render {

std::optional<float> ExposureMeter::measure(const Inputs& in) {
    std::string error;
    if (!mSmall) {
        mSmall = gl::createTargetTexture({GL_RGBA32F, "render/exposure/meter"},
                {kMeterSize, kMeterSize});
        mSmallFramebuffer = gl::createFramebuffer("render/exposure/meter");
        mSourceFramebuffer = gl::createFramebuffer("render/exposure/source");
        if (!gl::attachFramebuffer(mSmallFramebuffer, "render/exposure/meter", {&mSmall},
                    nullptr, error)) {
            std::fprintf(stderr, "voxatlas: %s\n", error.c_str());
        }
    }
    // The radiance texture is reallocated when the window resizes: attach it every time.
    if (!gl::attachFramebuffer(mSourceFramebuffer, "render/exposure/source", {&in.radiance},
                nullptr, error)) {
        return std::nullopt;
    }
    glBlitNamedFramebuffer(mSourceFramebuffer.id(), mSmallFramebuffer.id(), 0, 0, in.size.x,
            in.size.y, 0, 0, kMeterSize, kMeterSize, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    std::vector<float> rgba(std::size_t(kMeterSize) * kMeterSize * 4);
    glGetTextureImage(mSmall.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
            rgba.data());
    core::Image image(kMeterSize, kMeterSize);
    std::vector<float> coverage(std::size_t(kMeterSize) * kMeterSize);
    for (std::size_t i = 0; i < coverage.size(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgba[i * 4 + c] * in.scale;
        coverage[i] = rgba[i * 4 + 3];
    }
    return core::logAverageLuminance(image, coverage);
}

} // namespace gi::render
