// The sparse voxel octree of vpl.visibility=svo, kept while nothing it was built from
// changes: built on first use and again when the scene's geometry moves (its geometry
// version) or vpl.svo_resolution / vpl.svo_budget_mb change, as the voxel cache revoxelizes.
// The octree spans the scene's bounds (SparseVoxelOctree::cubeAround).
#pragma once

#include "core/Settings.h"
#include "gi/vpl/SparseVoxelOctree.h"

namespace gi::vpl {

class SvoVisibility {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error) {
        return mOctree.init(shaders, error);
    }
    // Refuses a vpl.svo_resolution that is not a power of two (one line in `error`).
    static bool validate(const VplSettings& settings, std::string& error);
    // The octree for this frame, rebuilt if stale; nullptr when the last build was refused
    // (failure() says why) and nothing occludes.
    const SparseVoxelOctree* update(const scene::GpuScene& scene, const VplSettings& settings,
            gl::GpuProfiler& profiler);
    // Why the octree was refused (over vpl.svo_budget_mb), or empty.
    const std::string& failure() const { return mFailure; }
    const SparseVoxelOctree& octree() const { return mOctree; }

private:
    struct Source {
        const scene::GpuScene* scene = nullptr;
        std::uint64_t geometryVersion = 0;
        int resolution = 0;
        int budgetMb = 0;
        bool operator==(const Source&) const = default;
    };

    SparseVoxelOctree mOctree;
    Source mSource;
    std::string mFailure;
};

} // namespace gi::vpl
