// Fills each coarser cascade level's centre from the finer level with a coverage-weighted
// 2x2x2 average (thesis 4.3.3.3, Listings 4.3/4.4), one compute dispatch per level.
// Inputs : VoxelTextures level L-1 (albedo, normal, irradiance), VoxelUniforms.
// Outputs: the same textures, centre (v/2)^3 voxels of levels 1..l-1.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class PropagatePass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement, coverage mode
    };
    struct Outputs {
        // albedo (rgba16f, x coverage), normal (rgba8_snorm), irradiance (rgba16f, W/m^2 x
        // coverage): each level L >= 1 is read from level L-1 and written in place.
        const VoxelTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::voxel
