#include "gi/voxel/StaticVoxelCache.h"

#include "gl/Shared.h"

namespace gi::voxel {
namespace {

void copyVolume(const gl::Texture& from, const gl::Texture& to, glm::ivec3 size) {
    glCopyImageSubData(from.id(), GL_TEXTURE_3D, 0, 0, 0, 0, to.id(), GL_TEXTURE_3D, 0, 0, 0, 0,
            size.x, size.y, size.z);
}

glm::ivec3 cascadeSize(const VoxelTextures& t) {
    return {t.resolution, t.resolution, t.resolution * t.levels};
}

glm::ivec3 directionalSize(const VoxelTextures& t) {
    return {t.resolution * VOXEL_FACES, t.resolution, t.resolution * t.levels};
}

} // namespace

void StaticVoxelCache::save(const VoxelTextures& t) {
    if (mResolution != t.resolution || mLevels != t.levels || mAnisotropic != t.anisotropic ||
            !mAlbedo) {
        mResolution = t.resolution;
        mLevels = t.levels;
        mAnisotropic = t.anisotropic;
        const glm::ivec3 size = cascadeSize(t);
        mAlbedo = gl::createTexture3D(GL_RGBA16F, size, 1, "voxel/static/albedo");
        mNormal = gl::createTexture3D(GL_RGBA8_SNORM, size, 1, "voxel/static/normal");
        mIrradiance = gl::createTexture3D(GL_RGBA16F, size, 1, "voxel/static/irradiance");
        mLock = gl::createTexture3D(GL_R32UI, size, 1, "voxel/static/lock");
        mDirectional = t.anisotropic
                ? gl::createTexture3D(GL_RGBA16F, directionalSize(t), 1, "voxel/static/directional")
                : gl::Texture();
    }
    copyVolume(t.albedo, mAlbedo, cascadeSize(t));
    copyVolume(t.normal, mNormal, cascadeSize(t));
    copyVolume(t.irradiance, mIrradiance, cascadeSize(t));
    copyVolume(t.lock, mLock, cascadeSize(t));
    if (t.anisotropic) copyVolume(t.directional, mDirectional, directionalSize(t));
}

bool StaticVoxelCache::restore(const VoxelTextures& t) const {
    if (!mAlbedo || mResolution != t.resolution || mLevels != t.levels ||
            mAnisotropic != t.anisotropic) {
        return false;
    }
    copyVolume(mAlbedo, t.albedo, cascadeSize(t));
    copyVolume(mNormal, t.normal, cascadeSize(t));
    copyVolume(mIrradiance, t.irradiance, cascadeSize(t));
    copyVolume(mLock, t.lock, cascadeSize(t));
    if (t.anisotropic) copyVolume(mDirectional, t.directional, directionalSize(t));
    // The helper is zero after every injection (inject_finalize.comp) but not after an
    // occupancy-only update, which never injects; clear it so both paths start alike.
    glClearTexImage(t.helper.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    return true;
}

void StaticVoxelCache::release() {
    *this = StaticVoxelCache();
}

} // namespace gi::voxel
