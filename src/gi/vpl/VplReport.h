// What the VPL technique holds and costs, for --timings, the viewer's overlay and `info`: the
// VPLs and the clamp of the last resampling, the visibility the gather used, what the last
// resampling took (the RSMs drawn and read back, the VPLs drawn from them: both run only when
// lights or geometry change, so a steady frame's pass list does not hold them), and the GPU
// memory the mode plans for a render size.
#pragma once

#include "core/Settings.h"
#include "gl/GpuProfiler.h"
#include "gl/MemoryRegistry.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi::vpl {

struct VplReport {
    int count = 0;               // VPLs drawn at the last resampling, both generations
    int secondGeneration = 0;    // of them found by vpl.bounces=2's rays
    float clampArea = 0.0f;      // B of 1 / max(B, r^2), m^2 (per VPL when clampFromScene:
                                 // that of a VPL standing for the mean lit area)
    bool clampFromScene = true;  // vpl.clamp = 0: B follows the surface each VPL stands for
    std::string visibility;      // vpl.visibility's name, or "none" when the frame had no
                                 // occupancy to march
    bool interleave = true;
    int rsmViews = 0;            // light views the RSMs were drawn through
    int rsmResolution = 0;
    std::size_t rsmTexels = 0;   // lit texels read back
    double rsmMs = 0.0;          // drawing and reading back every view's RSM (wall clock)
    double samplingMs = 0.0;     // drawing the first generation by flux (wall clock)
    int resamples = 0;           // resamplings since the technique was created
};

// vpl.visibility's name as --set takes it.
[[nodiscard]] std::string visibilityName(const VplSettings& settings);

// One line: "VPL: 1024 VPLs, B 0.00037 m^2 (auto), visibility cascade, 4x4 tiles | last
// resampling: RSM 12 views 1064 ms, sampling 3.1 ms | gbuffer 0.5, gather 6.2, filter 0.2 ms".
// The per-frame passes are the profiler's running means.
[[nodiscard]] std::string describeVpl(const VplReport& report,
        const std::vector<gl::PassTiming>& passes);

// The GPU memory the mode allocates at `settings` for a render of `renderSize` pixels, a row
// per label as the renderer reports it: one set of RSM textures (every light view is drawn
// into it in turn and read back), the VPL buffer, the uniforms (the octree's too, made with the
// technique), the camera G-buffer, the gather's interleaved result and the filter's merged one.
// Not included: the voxel occupancy that vpl.visibility=cascade marches (the voxel mode's,
// reported under "occupancy/") and the sparse voxel octree of vpl.visibility=svo, whose size
// depends on the geometry (at most vpl.svo_budget_mb of nodes).
[[nodiscard]] std::vector<gl::MemoryItem> plannedVplMemory(const VplSettings& settings,
        glm::ivec2 renderSize);

} // namespace gi::vpl
