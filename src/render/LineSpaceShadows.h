// The N-tree line space on the GPU for shadow.method=linespace (render/LineSpaceLayout.h,
// shaders/common/linespace.glsl), built when the method is first used and again when the
// geometry, the area lights or linespace.n / linespace.depth change:
//  1. compute: every shadow-casting triangle marks the leaf voxels it touches (conservative);
//  2. compute: each level's occupancy is reduced from the level below, up to the root;
//  3. CPU: the inner levels' occupancy is read back and the non-empty inner nodes numbered
//     level by level (breadth first), so the nodes above the deepest inner level come first
//     and node i's children are slots i N^3 .. (i + 1) N^3 - 1 of the node pool;
//  4. compute: one group per node writes its line space's bits (linespace_shafts.comp).
// The node pool (header, then child pointers, LINESPACE_EMPTY for empty children) and the
// line-space pool (15 N^4 bits per node, packed in uints, in node order) stay; the triangles
// and the occupancy are freed after the build.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "render/LineSpaceLayout.h"
#include "scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gi::render {

struct LineSpaceStats {
    int n = 0, depth = 0;
    std::size_t triangles = 0;
    std::size_t nodes = 0;            // non-empty inner nodes, each with a line space
    std::size_t bytes = 0;            // node pool + line-space pool
    double buildMilliseconds = 0.0;   // wall clock, build passes to glFinish
};

class LineSpaceShadows {
public:
    // Rebuilds when `geometryVersion` or n / depth differ from the last build (the programs
    // are built on first use). False with `error` when the build fails: nothing is occluded
    // then, and it is not tried again for the same inputs. A build is timed as the pass
    // render/linespace/build.
    bool update(gl::ShaderLibrary& shaders, const scene::Scene& scene,
            std::uint64_t geometryVersion, const LineSpaceSettings& settings,
            gl::GpuProfiler& profiler, std::string& error);
    // Binds the node and line-space pools (an empty tree before the first build).
    void bind();
    const LineSpaceStats& stats() const { return mStats; }

private:
    bool buildPrograms(gl::ShaderLibrary& shaders, std::string& error);
    bool build(const scene::Scene& scene, int n, int depth, std::string& error);
    // Numbers the non-empty inner nodes from the occupancy of levels 0 .. depth - 1.
    void allocateNodes(const LineSpaceLayout& layout, const std::vector<std::uint32_t>& occupancy,
            std::vector<std::uint32_t>& children, std::vector<glm::uvec4>& cells) const;

    gl::ProgramRef mVoxelize, mReduce, mShafts;
    gl::Buffer mNodes, mBits;
    LineSpaceStats mStats;
    bool mBuilt = false;
    std::uint64_t mGeometryVersion = 0;
};

} // namespace gi::render
