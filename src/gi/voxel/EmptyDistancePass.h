// Writes into every empty voxel of the coarsest cascade level its Chebyshev distance to the
// nearest occupied voxel (1 = a neighbour is occupied; at most kEmptyDistanceCap + 1), in its
// own normal texel (voxelEmptyTexel, voxel_plane.glsl). Cone tracing's walk learns from the one
// texel it fetches a step how far it may go at once: out of the cube of empty voxels around
// it, where it read the radiance pyramid's mip-1 coverage besides and crossed aligned 4^3
// blocks (results-performance.md).
// Three dispatches, one per axis (the transform is separable: the distance along x, then the
// least max(|dy|, that) over y, then over z), each a window of kEmptyDistanceCap voxels to
// either side, through two R8UI scratch volumes of the coarsest level.
// Inputs : VoxelTextures normal of the coarsest level, propagated (an occupied voxel's texel is
//          never an empty one), VoxelUniforms.
// Outputs: VoxelTextures normal: the coarsest level's empty voxels' texels.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class EmptyDistancePass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement
    };
    struct Outputs {
        // normal: the coarsest level read and its empty voxels written; distanceScratch:
        // overwritten
        const VoxelTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::voxel
