// The second generation of VPLs (vpl.bounces=2; shaders/vpl/bounce.comp): rays from the first
// generation's VPLs, cosine-distributed about their normals, marched through the voxel
// occupancy to the first surface they meet, each hit a VPL of the flux that surface reflects
// (phi_parent x its voxel albedo x parents / rays; the shader derives the factor). Runs only
// when the VPLs are drawn anew, so its readback stalls no steady frame.
// Inputs : the first generation, the number of rays, the voxel occupancy (albedo, coverage,
//          planes).
// Outputs: the second generation on the CPU, in ray order, rays that left the scene dropped.
#pragma once

#include "gi/GiTechnique.h"
#include "gl/Shared.h"

#include <string>
#include <vector>

namespace gi::vpl {

class VplBouncePass {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    [[nodiscard]] std::vector<shader::GpuVpl> execute(const std::vector<shader::GpuVpl>& parents,
            int rays, const OccupancyVolume& occupancy, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::vpl
