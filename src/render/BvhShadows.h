// The scene's BVH on the GPU for shadow.method=bvh (reference/GpuBvh.h, shaders/common/bvh.glsl):
// built on the CPU when the method is first used and again whenever the geometry moves or
// the area lights change (their own triangles are left out, as from their shadow maps).
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "reference/GpuBvh.h"
#include "scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gi::render {

class BvhShadows {
public:
    // Rebuilds when `geometryVersion` differs from the last build.
    // False with `error` when the build fails (the previous buffers stay).
    // A build is timed as the pass render/bvh/build.
    bool update(const scene::Scene& scene, std::uint64_t geometryVersion,
            gl::GpuProfiler& profiler, std::string& error);
    // Binds the node and triangle buffers (empty ones before the first build).
    void bind();
    const reference::GpuBvh& bvh() const { return mBvh; }

private:
    reference::GpuBvh mBvh;
    gl::Buffer mNodes, mTriangles;
    bool mBuilt = false;
    std::uint64_t mGeometryVersion = 0;
};

} // namespace gi::render
