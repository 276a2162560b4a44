// Marks the empty blocks of VOXEL_BLOCK^3 voxels of the coarsest cascade level in the voxels'
// own normal texels (kEmptyBlockTexel, voxel_plane.glsl), so cone tracing's walk learns from
// the one texel it fetches a step whether it may cross the whole block in one step, where it
// read the radiance pyramid's mip-1 coverage besides (results-performance.md).
// Inputs : VoxelTextures normal of the coarsest level, propagated (an occupied voxel's texel is
//          never all zero), VoxelUniforms.
// Outputs: VoxelTextures normal: every texel of a block whose voxels are all empty set to
//          kEmptyBlockTexel.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class EmptyBlocksPass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement
    };
    struct Outputs {
        const VoxelTextures& textures;     // normal, the coarsest level read and marked
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::voxel
