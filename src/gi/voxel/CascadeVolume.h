// Placement of the voxel cascade (thesis 4.2.1, 4.3.2): l nested levels of v^3 voxels, all
// centred on the camera, level k covering 2^k times the finest level's edge. The centre is
// snapped to the coarsest level's voxel size, so every level's grid stays aligned with the
// world as the camera moves (voxels do not swim) and each coarse voxel covers exactly 2x2x2
// voxels of the next finer level. All levels share one 3D texture of size (v, v, v*l):
// level k occupies z-slices [k*v, (k+1)*v).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace gi::voxel {

class CascadeVolume {
public:
    static constexpr int kMaxLevels = 8;

    CascadeVolume() = default;
    // finestExtent: edge length of level 0 in metres.
    CascadeVolume(int resolution, int levels, float finestExtent);

    // Re-centres all levels on `center`, snapped to the coarsest voxel size. Returns true if
    // the placement changed.
    bool placeAround(const glm::vec3& center);

    int resolution() const { return mResolution; }
    int levels() const { return mLevels; }
    float extent(int level) const { return mFinestExtent * float(1 << level); }
    float voxelSize(int level) const { return extent(level) / float(mResolution); }
    glm::vec3 origin(int level) const { return mOrigins[std::size_t(level)]; }
    glm::vec3 center() const { return mCenter; }

    // Finest level whose region contains p, or nothing if p is outside the coarsest level.
    [[nodiscard]] std::optional<int> finestLevelContaining(const glm::vec3& p) const;
    // Voxel coordinate of p inside `level` (texel of that level, before the z-slab offset).
    [[nodiscard]] glm::ivec3 voxelOf(const glm::vec3& p, int level) const;
    // World-space centre of a voxel of `level`.
    [[nodiscard]] glm::vec3 voxelCenter(const glm::ivec3& voxel, int level) const;

    // Texels of one 3D texture of the cascade: v * v * (v * l).
    [[nodiscard]] std::size_t texelCount() const;

    // Edge of the finest level that lets the coarsest level reach every corner of `bounds`
    // from `eye` (the default when voxel.extent is 0), never smaller than 1e-6 m.
    [[nodiscard]] static float finestExtentFor(const scene::Aabb& bounds, const glm::vec3& eye,
            int levels);

    // Edge of a finest level that holds all of `bounds` when centred on it (voxel.center=scene),
    // with room for the snap to the coarsest voxel size.
    [[nodiscard]] static float finestExtentCovering(const scene::Aabb& bounds);

private:
    int mResolution = 32, mLevels = 3;
    float mFinestExtent = 1.0f;
    glm::vec3 mCenter{0.0f};
    std::array<glm::vec3, kMaxLevels> mOrigins{};
};

} // namespace gi::voxel
