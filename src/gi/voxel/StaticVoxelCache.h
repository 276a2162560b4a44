// The voxelization of a scene's static geometry, kept between frames (issue: model only what a
// scene requires). When a scene has animated instances, its static part is voxelized once per
// placement of the cascade and saved here; every frame restores it and voxelizes only the
// dynamic instances on top, before light injection. A copy holds what voxelization writes and
// injection later changes: albedo, normal, the area sum in irradiance.a and the fragment
// counts in the lock (so the dynamic fragments continue the same running averages), and with
// anisotropic voxels the per-face area sums of the directional copy.
// 24 bytes per voxel (72 anisotropic), allocated only for scenes with dynamic geometry.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/Objects.h"

#include <vector>

namespace gi::voxel {

class StaticVoxelCache {
public:
    // Copies the voxelization in `textures` into the cache (allocated to match on first use).
    void save(const VoxelTextures& textures);
    // Writes the saved voxelization back into `textures`; true if the cache matches its size.
    bool restore(const VoxelTextures& textures) const;
    void release();
    [[nodiscard]] bool allocated() const { return bool(mAlbedo); }

private:
    gl::Texture mAlbedo, mNormal, mIrradiance, mLock, mDirectional;
    int mResolution = 0, mLevels = 0;
    bool mAnisotropic = false;
};

} // namespace gi::voxel
