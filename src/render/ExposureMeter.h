// Meters a frame for the viewer's auto exposure, cheaply enough for every frame on a software
// rasteriser: the radiance texture is blitted (bilinear) down to kMeterSize^2 texels, read
// back (64 KiB), and core::logAverageLuminance runs over the texels whose coverage is above
// one half. The log-average of a downsample is not that of the full image (bright speckles
// are averaged before the log), a difference auto exposure does not notice.
// Inputs : radiance, RGBA32F linear radiance / scale, alpha = geometry coverage, any size.
// Outputs: the log-average luminance, W/(m^2 sr); nullopt when no texel shows geometry.
#pragma once

#include "gl/Objects.h"

#include <glm/glm.hpp>

#include <optional>

namespace gi::render {

class ExposureMeter {
public:
    static constexpr int kMeterSize = 64;

    struct Inputs {
        const gl::Texture& radiance;   // RGBA32F, linear radiance / scale, a = coverage
        glm::ivec2 size;               // texels of radiance
        float scale = 1.0f;            // FrameRenderer::radianceScale()
    };

    [[nodiscard]] std::optional<float> measure(const Inputs& in);

private:
    gl::Texture mSmall;
    gl::Framebuffer mSourceFramebuffer, mSmallFramebuffer;
};

} // namespace gi::render
