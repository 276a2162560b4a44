// Anisotropic voxels (voxel.anisotropic): builds the directional copy of the cascade, each
// voxel as seen from each of its 6 faces, level by level, finest first
// (shaders/voxel/directional_build.comp). Voxelized voxels copy their isotropic value to
// every face; propagated ones composite their finer children front to back per face.
// Inputs : VoxelTextures albedo (rgb x coverage, a = coverage) and irradiance (E x coverage,
//          W/m^2) of every level, propagated; VoxelUniforms.
// Outputs: VoxelTextures directional, every level (rgb = rho E x a, a = facing coverage).
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class DirectionalVoxelsPass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement
        const VoxelTextures& cascade;      // albedo and irradiance, propagated
    };
    struct Outputs {
        const VoxelTextures& textures;     // directional, every level written
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::voxel
