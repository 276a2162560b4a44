// What the active shadow method (shadow.method) holds and costs, for --timings, the viewer's
// overlay and `info`: the structure it traces, when it was last built and for how long, and
// the GPU memory it takes. The per-frame cost of its rays is inside the render/forward pass.
#pragma once

#include "core/Settings.h"
#include "scene/Scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace gi::render {

struct ShadowMethodReport {
    std::string method;       // shadow.method's name ("off" with shadow.enabled=0)
    int rays = 0;             // rays per pixel and area light; 0 for shadow maps and cones
    std::string structure;    // what it traces, e.g. "LS(6,3) over 30 triangles, 8217 nodes"
    double buildMs = 0.0;     // its last build (0 when it has none or was not built yet)
    std::size_t bytes = 0;    // GPU memory of its structures
    bool bound = false;       // bytes is an upper bound made before building (`info`)
};

// Levels of the voxel occupancy that shadow.method=voxel reads (finest voxel x 1, 2, 4): the
// coarser ones are the pre-filtered footprints of a cone widening towards an area light.
inline constexpr int kShadowConeLevels = 3;

// shadow.method's name as --set takes it.
[[nodiscard]] const char* shadowMethodName(int method);

// One line: "shadows: bvh, 25 rays, BVH over 30 triangles (12 nodes), built in 1 ms, 0.01 MiB".
[[nodiscard]] std::string describeShadowMethod(const ShadowMethodReport& report);

// Before anything is built (`info`): the method at `settings` (the plan applied) and an upper
// bound of what its structures take for `lights`.
[[nodiscard]] ShadowMethodReport plannedShadowMethod(const scene::Scene& scene,
        const std::vector<scene::Light>& lights, const Settings& settings);

} // namespace gi::render
