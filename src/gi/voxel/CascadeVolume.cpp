#include "gi/voxel/CascadeVolume.h"

#include <algorithm>
#include <cmath>

namespace gi::voxel {

CascadeVolume::CascadeVolume(int resolution, int levels, float finestExtent)
    : mResolution(resolution), mLevels(std::clamp(levels, 1, kMaxLevels)),
      mFinestExtent(finestExtent) {
    placeAround(glm::vec3(0.0f));
}

bool CascadeVolume::placeAround(const glm::vec3& center) {
    const double snap = double(voxelSize(mLevels - 1));
    // Snapping in double keeps the grid exact for cameras far from the origin (1e5 m).
    const glm::dvec3 snapped = glm::floor(glm::dvec3(center) / snap + 0.5) * snap;
    const glm::vec3 newCenter(snapped);
    const bool changed = newCenter != mCenter;
    mCenter = newCenter;
    for (int level = 0; level < mLevels; ++level) {
        mOrigins[std::size_t(level)] = glm::vec3(snapped - 0.5 * double(extent(level)));
    }
    return changed;
}

std::optional<int> CascadeVolume::finestLevelContaining(const glm::vec3& p) const {
    for (int level = 0; level < mLevels; ++level) {
        const glm::vec3 local = p - origin(level);
        const float e = extent(level);
        if (local.x >= 0.0f && local.y >= 0.0f && local.z >= 0.0f && local.x < e && local.y < e &&
                local.z < e) {
            return level;
        }
    }
    return std::nullopt;
}

glm::ivec3 CascadeVolume::voxelOf(const glm::vec3& p, int level) const {
    const glm::ivec3 v(glm::floor((p - origin(level)) / voxelSize(level)));
    return glm::clamp(v, glm::ivec3(0), glm::ivec3(mResolution - 1));
}

glm::vec3 CascadeVolume::voxelCenter(const glm::ivec3& voxel, int level) const {
    return origin(level) + (glm::vec3(voxel) + 0.5f) * voxelSize(level);
}

std::size_t CascadeVolume::texelCount() const {
    const auto v = std::size_t(mResolution);
    return v * v * v * std::size_t(mLevels);
}

float CascadeVolume::finestExtentFor(const scene::Aabb& bounds, const glm::vec3& eye, int levels) {
    float reach = 0.0f;
    if (!bounds.empty()) {
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x,
                    (i & 2) ? bounds.max.y : bounds.min.y, (i & 4) ? bounds.max.z : bounds.min.z);
            const glm::vec3 d = glm::abs(corner - eye);
            reach = std::max(reach, std::max(d.x, std::max(d.y, d.z)));
        }
    }
    // The coarsest level spans 2 * reach (centred on the eye) plus one coarse voxel of
    // snapping slack on either side.
    const float coarsest = std::max(2.0f * reach * 1.1f, 1e-6f);
    return coarsest / float(1 << (std::clamp(levels, 1, kMaxLevels) - 1));
}

float CascadeVolume::finestExtentCovering(const scene::Aabb& bounds) {
    const glm::vec3 size = bounds.size();
    return std::max(std::max(size.x, std::max(size.y, size.z)) * 1.1f, 1e-6f);
}

} // namespace gi::voxel
