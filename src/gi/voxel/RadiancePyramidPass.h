// Averages the coarsest cascade level into a mipmapped pyramid of reflected light, so a cone
// wider than the coarsest voxels still reads the light over its own footprint rather than
// over one voxel (the pre-filtering of Crassin et al. 2011, "Interactive Indirect Illumination
// Using Voxel Cone Tracing", applied above the cascade, whose nested levels stop there).
// Mip 0 averages 2x2x2 coarsest voxels of rho E x coverage and of coverage; each further mip
// averages 2x2x2 texels of the previous one. One dispatch per mip. With anisotropic voxels
// every mip holds the 6 faces instead, composited front to back from the directional voxels
// (directional_pyramid.comp).
// Inputs : VoxelTextures albedo (rgb x coverage, a = coverage) and irradiance (E x coverage,
//          W/m^2) of the coarsest level; VoxelUniforms.
//          Anisotropic: VoxelTextures directional of the coarsest level instead.
// Outputs: VoxelTextures pyramid, every mip (rgb = rho E x coverage, a = coverage; per face
//          when anisotropic).
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
