// A bounding volume hierarchy over the scene's triangles for ray tracing in shaders (the
// `bvh` shadow method, the exact baseline line-space visibility is measured against): built
// by Embree's BVH builder (rtcBuildBVH: binned SAH, two children per node, at most
// kMaxLeafTriangles per leaf) and flattened depth first, so the left child of node i is
// node i + 1 and a shader walks the tree with a short stack (shaders/common/bvh.glsl).
#pragma once

#include "gl/Shared.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace gi::reference {

inline constexpr unsigned kMaxLeafTriangles = BVH_MAX_LEAF_TRIANGLES;

struct GpuBvh {
    // Two vec4 per node, the layout of GpuBvhNode (shaders/common/shared.h):
    // (min.xyz, inner: index of the right child / leaf: -(triangle count), as int bits),
    // (max.xyz, leaf: first triangle, as int bits).
    std::vector<glm::vec4> nodes;
    std::vector<glm::vec4> triangles;   // three corners per triangle, world space, w as given
    int depth = 0;                      // longest root-to-leaf path (the shader's stack bound)
    double buildSeconds = 0.0;
    std::size_t nodeCount() const { return nodes.size() / 2; }
    std::size_t triangleCount() const { return triangles.size() / 3; }
    std::size_t bytes() const { return (nodes.size() + triangles.size()) * sizeof(glm::vec4); }
};

// Over the triangles given as three world-space corners each (w kept with its corner, unread;
// render/ShadowCasters.h collects them). False with `error` when Embree fails.
bool buildGpuBvh(const std::vector<glm::vec4>& corners, GpuBvh& bvh, std::string& error);

} // namespace gi::reference
