// One more bounce of light in the voxels (gi.bounces > 1; shaders/voxel/bounce.comp): every
// occupied voxel its level voxelized traces every diffuse cone from its surface through the
// cascade as it is lit now, and its irradiance becomes the injected direct light plus what the
// cones gathered. The caller then propagates again and rebuilds the radiance pyramid, so the next
// gather (the next bounce, or the screen-space trace) sees light that has bounced once more.
// Inputs : VoxelTextures albedo, normal, irradiance and pyramid as propagated (sampled by the
//          cones); VoxelUniforms; FrameUniforms (the sky a cone sees where it escapes).
// Outputs: VoxelTextures irradiance of the voxelized voxels (E_direct + gathered, x coverage)
//          and gathered (what was added, for the next bounce); the helper is left cleared.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class BouncePass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement, cone parameters
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140: the sky's radiance
        bool first;                        // the first further bounce: nothing gathered yet
    };
    struct Outputs {
        const VoxelTextures& textures;     // irradiance and gathered updated, helper cleared
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mGather, mApply;
};

} // namespace gi::voxel
