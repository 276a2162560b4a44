// The sparse voxel octree vpl.visibility=svo marches (SEEDS.md section 4: Sun and Agu 2015
// build it as Crassin and Green, "Octree-Based Sparse Voxelization Using the GPU Hardware
// Rasterizer", OpenGL Insights 2012, ch. 22), built on the GPU without recursion:
//   1. the voxel fragment list: the scene is rasterized along each triangle's dominant axis
//      at kRasterPerLeaf pixels per leaf voxel; each fragment sets its leaf's bit in a grid,
//      and the fragment that set it appends the leaf to the list (shaders/vpl/svo_voxelize.*);
//   2. top down, one level at a time (shaders/vpl/svo_build.comp): flag the level's nodes
//      that hold a leaf, give each flagged node 8 children from an atomic counter and clear
//      them, and find the next level's node range and indirect dispatch; the leaf level is
//      flagged only;
//   3. the used part of the pool is copied into a buffer of its exact size.
// Layout: shaders/common/svo.glsl. The pool may hold budgetBytes at most: an octree that needs
// more is refused. Two small readbacks: the list's length (to size the pool) and the count.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "gl/Shared.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gi::vpl {

// The octree's cube: its lowest corner and its leaf voxels' edge (m).
struct SvoCube {
    glm::vec3 lowest{0.0f};
    float leafSize = 1.0f;
};

struct SvoStats {
    int resolution = 0;          // leaves per side
    int depth = 0;               // levels below the root
    std::size_t leaves = 0;      // occupied leaf voxels
    std::size_t nodes = 0;       // nodes in the octree, the root and every group of 8
    std::size_t bytes = 0;       // the octree's node buffer
    double buildMilliseconds = 0.0;   // wall clock, fragments to the final readback
};

class SparseVoxelOctree {
public:
    static constexpr int kRasterPerLeaf = 2;
    static constexpr std::size_t kBytesPerNode = sizeof(std::uint32_t);
    // How the march leaves the ends' surfaces, in leaf voxels (svo_visibility.glsl). A
    // shrink of one leaf lost a fifth of Sponza's indirect light to its surfaces' own leaves
    // (energy 0.78 against the path tracer, 0.89 with two, 0.94 with a push of two as well);
    // the Cornell box hardly changes, and the light leaking through two_rooms_thin_wall's
    // wall stays below 1e-4 of the lit room's (results-vpl.md).
    static constexpr float kEndPush = 1.0f;
    static constexpr float kEndShrink = 2.0f;
    static constexpr float kExitEpsilon = 1e-3f;

    // The cube over `bounds` with `resolution` leaves a side and one empty leaf of margin, so
    // surfaces on the bounds lie inside it.
    [[nodiscard]] static SvoCube cubeAround(const scene::Aabb& bounds, int resolution);

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Builds the octree of `scene` in `cube` at `resolution` (a power of two up to
    // 2^SVO_MAX_DEPTH). False with one line in `error` when it needs more than budgetBytes;
    // the octree is empty then (nothing occludes).
    bool build(const scene::GpuScene& scene, const SvoCube& cube, int resolution,
            std::size_t budgetBytes, gl::GpuProfiler& profiler, std::string& error);
    // Binds the nodes and SvoUniforms for the march.
    void bind() const;

    const SvoStats& stats() const { return mStats; }
    bool built() const { return mStats.nodes > 0; }
    // The loop iterations one segment of common/svo_visibility.glsl runs at most: its restarts,
    // each descending from the root through every level.
    [[nodiscard]] int visibilityLoopIterations() const {
        return SVO_VISIBILITY_MAX_STEPS * (mStats.depth + 2);
    }
    // For tests: every node word, and the occupied leaves of the last build's fragment list.
    [[nodiscard]] std::vector<std::uint32_t> readNodes() const;
    [[nodiscard]] std::vector<glm::uvec3> readFragmentLeaves() const;

private:
    void writeUniforms(const SvoCube& cube, int resolution, std::size_t capacity);
    // Fills the fragment list (grown and redone when it overflows); returns its length.
    std::size_t voxelize(const scene::GpuScene& scene, int resolution, gl::GpuProfiler& profiler);
    std::size_t runVoxelization(const scene::GpuScene& scene, int resolution);
    // The level passes into a pool of `capacity` nodes; false if they overflowed it.
    bool buildLevels(std::size_t leaves, std::size_t capacity, int depth,
            gl::GpuProfiler& profiler, std::size_t& nodes);

    gl::ProgramRef mVoxelize, mFlag, mAllocate, mAdvance;
    gl::Framebuffer mFramebuffer;   // no attachments: rasterization only
    gl::Buffer mUniforms;
    gl::Buffer mLeafBits, mFragments, mBuildState;
    gl::Buffer mPool, mNodes;
    std::size_t mFragmentCapacity = 0;
    SvoStats mStats;
};

} // namespace gi::vpl
