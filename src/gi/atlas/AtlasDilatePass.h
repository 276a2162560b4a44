// Normalisation and dilation (shaders/atlas/dilate.frag): the gather sums times 1/N over
// every set so far give E_ind per texel; empty texels within atlas.dilation.x texels of a
// chart take its nearest texels' mean, so bilinear lookups at chart borders never read black.
// With atlas.filter each written texel takes the tent-weighted mean of its block's texels on
// its own surface. Which neighbours those are depends on the G-buffer alone: drawSurfaceMask()
// draws it into AtlasTextures surfaceMask (shaders/atlas/surface_mask.frag) once per G-buffer,
// and every dilation after it reads it.
// Inputs : AtlasTextures sums and surfaceMask (the mask: normal and position), AtlasUniforms
//          (sampling.w = 1 / samples, dilation radius, filter).
// Outputs: AtlasTextures lit (RGBA16F, rgb = E_ind in W/m^2, a = 1 surface / 0.5 dilated).
#pragma once

#include "gi/atlas/AtlasTexelPass.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::atlas {

class AtlasDilatePass {
public:
    struct Inputs {
        const AtlasTextures& textures;     // sums (RGBA32F, rgb = gather sums, a = written)
        const gl::Buffer& atlasUniforms;   // AtlasUniforms, std140: R, 1 / samples, radius
        int bounce = 0;                    // the sums read: textures.sumsOf(bounce)
    };
    struct Outputs {
        const AtlasTextures& textures;     // lit, the layer attach() bound
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Draws into textures.lit and textures.surfaceMask from now on; false with a message if
    // they are not renderable.
    bool attach(const AtlasTextures& textures, std::string& error);
    // The filter's surface mask from the G-buffer (in.bounce is not used).
    void drawSurfaceMask(const Inputs& in, gl::GpuProfiler& profiler);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    AtlasTexelPass mPass, mMaskPass;
    gl::Framebuffer mFramebuffer, mMaskFramebuffer;
    int mResolution = 0;
};

} // namespace gi::atlas
