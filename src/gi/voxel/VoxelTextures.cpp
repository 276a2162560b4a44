#include "gi/voxel/VoxelTextures.h"

namespace gi::voxel {
namespace {

gl::Texture createVolume(GLenum format, int v, int l, const char* label) {
    gl::Texture texture = gl::createTexture3D(format, {v, v, v * l}, 1, label);
    const GLint filter = format == GL_R32UI ? GL_NEAREST : GL_LINEAR;
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, filter);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    }
    return texture;
}

} // namespace

void VoxelTextures::allocate(int v, int l) {
    resolution = v;
    levels = l;
    albedo = createVolume(GL_RGBA16F, v, l, "voxel/albedo");
    normal = createVolume(GL_RGBA8_SNORM, v, l, "voxel/normal");
    irradiance = createVolume(GL_RGBA16F, v, l, "voxel/irradiance");
    helper = createVolume(GL_RGBA16F, v, l, "voxel/helper");
    lock = createVolume(GL_R32UI, v, l, "voxel/lock");
    pyramid = gl::createTexture3D(GL_RGBA16F, glm::ivec3(v / 2), pyramidLevels(), "voxel/pyramid");
    glTextureParameteri(pyramid.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(pyramid.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTextureParameteri(pyramid.id(), wrap, GL_CLAMP_TO_EDGE);
    }
}

int VoxelTextures::pyramidLevels() const {
    return gl::fullMipCount(resolution / 2);
}

void VoxelTextures::clear() const {
    for (const gl::Texture* t : {&albedo, &normal, &irradiance, &helper}) {
        glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    }
    glClearTexImage(lock.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

std::vector<gl::MemoryItem> VoxelTextures::memoryFor(int v, int l) {
    const glm::ivec3 size(v, v, v * l);
    return {{"voxel/albedo", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/normal", gl::textureBytes(GL_RGBA8_SNORM, size, 1)},
            {"voxel/irradiance", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/helper", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/lock", gl::textureBytes(GL_R32UI, size, 1)},
            {"voxel/pyramid", gl::textureBytes(GL_RGBA16F, glm::ivec3(v / 2), gl::fullMipCount(v / 2))}};
}

} // namespace gi::voxel
