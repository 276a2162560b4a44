// The shape of the N-tree behind shadow.method=linespace (Keul, Klee, Mueller, "Soft shadow
// computation using precomputed line space visibility information", SEEDS.md section 3):
// the root is a cube around the scene, every inner node splits into N x N x N children, and
// the leaves (the voxels the scene is marked in) lie `depth` levels below the root, N^depth
// per axis. Every non-empty inner node stores a line space: one bit per pair of its 6 N^2
// boundary sub-faces on different faces, 15 N^4 bits (render/LineSpaceShadows.h).
#pragma once

#include "core/Settings.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gi::render {

struct LineSpaceLayout {
    int n = 6;
    int depth = 3;
    glm::vec3 rootMin{0.0f};
    float rootSize = 1.0f;

    // Cells per axis of level `level` (0 = the root, depth = the leaves).
    [[nodiscard]] std::uint64_t resolution(int level) const;
    [[nodiscard]] std::uint64_t cells(int level) const;
    [[nodiscard]] float leafSize() const { return rootSize / float(resolution(depth)); }
    // Where each level's occupancy bits start in the occupancy buffer, in uints, and its total.
    [[nodiscard]] std::uint64_t occupancyOffset(int level) const;
    [[nodiscard]] std::uint64_t occupancyWords() const { return occupancyOffset(depth + 1); }
    [[nodiscard]] std::uint64_t shaftsPerNode() const;
    [[nodiscard]] std::uint64_t wordsPerNode() const { return (shaftsPerNode() + 31) / 32; }
};

// The root cube: the scene's bounds' longest side, 2% wider so that walls on the bounds do not
// lie on cell faces.
[[nodiscard]] LineSpaceLayout lineSpaceLayout(const scene::Aabb& bounds, int n, int depth);

// An upper bound of the GPU memory the line space of `corners` (ShadowCasters.h) takes, build
// buffers included: the nodes are counted as the cells of the deepest inner level that the
// triangles' bounding boxes touch, and their ancestors.
[[nodiscard]] double lineSpaceBytesBound(const LineSpaceLayout& layout,
        const std::vector<glm::vec4>& corners);

// False with one line when shadow.method=linespace at `settings` would exceed the resource
// budget (gl/Limits.h); true for the other methods.
[[nodiscard]] bool lineSpaceFits(const scene::Scene& scene, const Settings& settings,
        std::string& error);

} // namespace gi::render
