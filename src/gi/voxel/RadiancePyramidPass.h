// Averages the coarsest cascade level into a mipmapped pyramid of reflected light, so a cone
// wider than the coarsest voxels still reads the light over its own footprint rather than
// over one voxel (the pre-filtering of Crassin et al. 2011, "Interactive Indirect Illumination
// Using Voxel Cone Tracing", applied above the cascade, whose nested levels stop there).
// Every mip holds the light as seen from each of the 6 faces (x-slabs, voxel_directional.glsl),
// so a cone reading it takes the surfaces that face it, not every surface a texel holds by its
// coverage (one average mixed a lit floor with the shaded flanks of the piers standing on it,
// and the ceiling with the walls beside a spot's patch: accuracy-analysis.md). Isotropic
// voxels (radiance_pyramid.comp): mip 0 averages 2x2x2 coarsest voxels of rho E x the area
// each face is shown (coverage x max(+-n_axis, 0), n the mean normal) and of that area; each
// further mip averages 2x2x2 texels of the previous one. A propagated coarsest level (a
// cascade of several levels), whose normals do not say which faces its surfaces show, gives
// every face the whole coverage: each face holds the one average. Anisotropic voxels
// (directional_pyramid.comp): composited front to back per face from the directional voxels.
// One dispatch per mip.
// Inputs : VoxelTextures albedo (rgb x coverage, a = coverage), irradiance (E x coverage,
//          W/m^2) and normal of the coarsest level; VoxelUniforms.
//          Anisotropic: VoxelTextures directional of the coarsest level instead.
// Outputs: VoxelTextures pyramid, every mip (per face: rgb = rho E x area, a = area).
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class RadiancePyramidPass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement
        // albedo (rgb x coverage, a = coverage) and irradiance (E x coverage, W/m^2) of the
        // coarsest level, propagated
        const VoxelTextures& cascade;
    };
    struct Outputs {
        const VoxelTextures& textures;     // pyramid, every mip written
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
    gl::ProgramRef mDirectionalProgram;
};

} // namespace gi::voxel
