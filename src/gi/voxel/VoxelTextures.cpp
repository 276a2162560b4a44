#include "gi/voxel/VoxelTextures.h"

#include "gl/Shared.h"

namespace gi::voxel {
namespace {

int facesOf(bool anisotropic) { return anisotropic ? VOXEL_FACES : 1; }

gl::Texture createVolume(GLenum format, glm::ivec3 size, const char* label) {
    gl::Texture texture = gl::createTexture3D(format, size, 1, label);
    const GLint filter = format == GL_R32UI || format == GL_R8UI ? GL_NEAREST : GL_LINEAR;
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, filter);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    }
    return texture;
}

} // namespace

void VoxelTextures::allocate(int v, int l, bool anisotropicVoxels, bool bounces, bool occupancy) {
    resolution = v;
    levels = l;
    anisotropic = anisotropicVoxels;
    const glm::ivec3 size(v, v, v * l);
    albedo = createVolume(GL_RGBA16F, size, "voxel/albedo");
    normal = createVolume(GL_RGBA8_SNORM, size, "voxel/normal");
    irradiance = createVolume(GL_RGBA16F, size, "voxel/irradiance");
    helper = createVolume(GL_RGBA16F, size, "voxel/helper");
    lock = createVolume(GL_R32UI, size, "voxel/lock");
    fluxSum = createVolume(GL_R32UI, {3 * v, v, v * l}, "voxel/flux_sum");
    gathered = bounces ? createVolume(GL_RGBA16F, size, "voxel/gathered") : gl::Texture();
    // Faces are fetched whole, never filtered.
    edgeFaces = occupancy ? createVolume(GL_RGBA8_SNORM, {2 * v, v, v}, "voxel/edge_faces")
                          : gl::Texture();
    if (occupancy) {
        glTextureParameteri(edgeFaces.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(edgeFaces.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    for (gl::Texture& scratch : distanceScratch) {
        scratch = createVolume(GL_R8UI, glm::ivec3(v), "voxel/distance_scratch");
    }
    const int faces = facesOf(anisotropic);
    directional = anisotropic
            ? createVolume(GL_RGBA16F, {v * faces, v, v * l}, "voxel/directional")
            : gl::Texture();
    // The pyramid keeps each face apart for isotropic voxels too (RadiancePyramidPass.h).
    pyramid = gl::createTexture3D(GL_RGBA16F, {v / 2 * VOXEL_FACES, v / 2, v / 2}, pyramidLevels(),
            "voxel/pyramid");
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
    // The flux sums are cleared by InjectPass, before each injection.
    glClearTexImage(lock.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    if (anisotropic) glClearTexImage(directional.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
}

std::vector<gl::MemoryItem> VoxelTextures::memoryFor(int v, int l, bool anisotropicVoxels,
        bool bounces, bool occupancy) {
    const glm::ivec3 size(v, v, v * l);
    const int faces = facesOf(anisotropicVoxels);
    std::vector<gl::MemoryItem> items = {{"voxel/albedo", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/normal", gl::textureBytes(GL_RGBA8_SNORM, size, 1)},
            {"voxel/irradiance", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/helper", gl::textureBytes(GL_RGBA16F, size, 1)},
            {"voxel/lock", gl::textureBytes(GL_R32UI, size, 1)},
            {"voxel/flux_sum", gl::textureBytes(GL_R32UI, {3 * v, v, v * l}, 1)},
            {"voxel/pyramid", gl::textureBytes(GL_RGBA16F, {v / 2 * VOXEL_FACES, v / 2, v / 2},
                    gl::fullMipCount(v / 2))}};
    if (bounces) items.push_back({"voxel/gathered", gl::textureBytes(GL_RGBA16F, size, 1)});
    if (occupancy) {
        items.push_back({"voxel/edge_faces", gl::textureBytes(GL_RGBA8_SNORM, {2 * v, v, v}, 1)});
    }
    items.push_back({"voxel/distance_scratch", 2 * gl::textureBytes(GL_R8UI, glm::ivec3(v), 1)});
    if (anisotropicVoxels) {
        items.push_back({"voxel/directional",
                gl::textureBytes(GL_RGBA16F, {v * faces, v, v * l}, 1)});
    }
    return items;
}

} // namespace gi::voxel
