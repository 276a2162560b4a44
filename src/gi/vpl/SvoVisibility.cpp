#include "gi/vpl/SvoVisibility.h"

#include <cstdio>

namespace gi::vpl {

bool SvoVisibility::validate(const VplSettings& settings, std::string& error) {
    const int r = settings.svoResolution;
    if (r > 0 && (r & (r - 1)) == 0) return true;
    error = "vpl.svo_resolution " + std::to_string(r) +
            " must be a power of two (16..1024): each octree level halves the one above";
    return false;
}

const SparseVoxelOctree* SvoVisibility::update(const scene::GpuScene& scene,
        const VplSettings& settings, gl::GpuProfiler& profiler) {
    const Source source{&scene, scene.geometryVersion(), settings.svoResolution,
            settings.svoBudgetMb};
    if (!(source == mSource)) {
        mSource = source;
        mFailure.clear();
        const std::size_t budget = std::size_t(settings.svoBudgetMb) << 20;
        const SvoCube cube = SparseVoxelOctree::cubeAround(scene.bounds(), source.resolution);
        if (mOctree.build(scene, cube, source.resolution, budget, profiler, mFailure)) {
            const SvoStats& s = mOctree.stats();
            std::fprintf(stderr,
                    "vpl: sparse voxel octree %d^3, %zu occupied leaves, %zu nodes, %.2f MiB, "
                    "built in %.1f ms\n",
                    s.resolution, s.leaves, s.nodes, double(s.bytes) / double(1 << 20),
                    s.buildMilliseconds);
        }
    }
    return mFailure.empty() ? &mOctree : nullptr;
}

} // namespace gi::vpl
