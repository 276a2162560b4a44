#include "gi/voxel/StaticVoxelCache.h"

namespace gi::voxel {
namespace {

void copyVolume(const gl::Texture& from, const gl::Texture& to, int v, int l) {
    glCopyImageSubData(from.id(), GL_TEXTURE_3D, 0, 0, 0, 0, to.id(), GL_TEXTURE_3D, 0, 0, 0, 0,
            v, v, v * l);
}

} // namespace

void StaticVoxelCache::save(const VoxelTextures& t) {
    if (mResolution != t.resolution || mLevels != t.levels || !mAlbedo) {
        mResolution = t.resolution;
        mLevels = t.levels;
        const glm::ivec3 size(t.resolution, t.resolution, t.resolution * t.levels);
        mAlbedo = gl::createTexture3D(GL_RGBA16F, size, 1, "voxel/static/albedo");
        mNormal = gl::createTexture3D(GL_RGBA8_SNORM, size, 1, "voxel/static/normal");
        mIrradiance = gl::createTexture3D(GL_RGBA16F, size, 1, "voxel/static/irradiance");
        mLock = gl::createTexture3D(GL_R32UI, size, 1, "voxel/static/lock");
    }
    copyVolume(t.albedo, mAlbedo, mResolution, mLevels);
    copyVolume(t.normal, mNormal, mResolution, mLevels);
    copyVolume(t.irradiance, mIrradiance, mResolution, mLevels);
    copyVolume(t.lock, mLock, mResolution, mLevels);
}

bool StaticVoxelCache::restore(const VoxelTextures& t) const {
    if (!mAlbedo || mResolution != t.resolution || mLevels != t.levels) return false;
    copyVolume(mAlbedo, t.albedo, mResolution, mLevels);
    copyVolume(mNormal, t.normal, mResolution, mLevels);
    copyVolume(mIrradiance, t.irradiance, mResolution, mLevels);
    copyVolume(mLock, t.lock, mResolution, mLevels);
    // The helper is zero after every injection (inject_finalize.comp) but not after an
    // occupancy-only update, which never injects; clear it so both paths start alike.
    glClearTexImage(t.helper.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    return true;
}

void StaticVoxelCache::release() {
    *this = StaticVoxelCache();
}

} // namespace gi::voxel
