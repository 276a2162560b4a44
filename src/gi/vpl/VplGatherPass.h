// The VPL gather (shaders/vpl/gather.comp): the indirect irradiance each VPL sends the surface
// of each pixel, through vpl.visibility, every VPL at every pixel or one interleaved subset
// per pixel (VplUniforms.counts.y).
// Inputs : the G-buffer, the VPLs, VplUniforms, the voxel occupancy (cascade visibility) or
//          the sparse voxel octree (svo visibility).
// Each pixel's VPLs are split over dispatches that each stay within SHADER_LOOP_ITERATIONS for
// the visibility's longest segments (gl/LoopBudget.h); each adds to what the last one stored.
// Outputs: result(), RGBA32F at the G-buffer's size: rgb = E_ind (W/m^2), a = view depth (m).
#pragma once

#include "gi/GiTechnique.h"
#include "gi/vpl/SparseVoxelOctree.h"
#include "gi/vpl/VplGBufferPass.h"

namespace gi::vpl {

class VplGatherPass {
public:
    struct Inputs {
        const VplGBufferPass& gBuffer;
        const gl::Buffer& vpls;               // GpuVpl[]
        const gl::Buffer& uniforms;           // VplUniforms
        const OccupancyVolume* occupancy;     // non-null: cascade visibility
        const SparseVoxelOctree* octree = nullptr;   // non-null: svo visibility
        int vplsPerPixel = 0;                 // the most VPLs one pixel's subset holds
        // > 0: visibility by rays through the scene's BVH bound at BIND_SSBO_BVH_*, each
        // running at most this many loop iterations.
        int bvhRayIterations = 0;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, gl::GpuProfiler& profiler);
    const gl::Texture& result() const { return mResult; }

private:
    gl::ProgramRef mUnoccluded;   // vpl.visibility=none
    gl::ProgramRef mCascade;      // vpl.visibility=cascade
    gl::ProgramRef mOctree;       // vpl.visibility=svo
    gl::ProgramRef mRays;         // vpl.visibility=bvh
    gl::Texture mResult;
    glm::ivec2 mSize{0};
};

} // namespace gi::vpl
