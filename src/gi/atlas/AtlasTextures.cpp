#include "gi/atlas/AtlasTextures.h"

#include <algorithm>

namespace gi::atlas {
namespace {

constexpr GLenum kDirectFormat = GL_RGBA16F, kNormalFormat = GL_RGBA16F,
                 kPositionFormat = GL_RGBA32F, kAlbedoFormat = GL_RGBA16F, kSumsFormat = GL_RGBA32F,
                 kLitFormat = GL_RGBA16F, kSurfaceMaskFormat = GL_R8UI;

gl::Texture layer(GLenum format, int resolution, GLenum filter, const char* label) {
    gl::Texture texture = gl::createTexture2D(format, {resolution, resolution}, 1, label);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

} // namespace

void AtlasTextures::allocate(int size, bool withBackSides, int bounceCount) {
    resolution = size;
    backSides = withBackSides;
    direct = layer(kDirectFormat, size, GL_NEAREST, "atlas/direct");
    normal = layer(kNormalFormat, size, GL_NEAREST, "atlas/normal");
    position = layer(kPositionFormat, size, GL_NEAREST, "atlas/position");
    albedo = layer(kAlbedoFormat, size, GL_NEAREST, "atlas/albedo");
    sums = layer(kSumsFormat, size, GL_NEAREST, "atlas/sums");
    lit = layer(kLitFormat, size, GL_LINEAR, "atlas/lit");
    surfaceMask = layer(kSurfaceMaskFormat, size, GL_NEAREST, "atlas/surface_mask");
    const int back = withBackSides ? size : 1;
    directBack = layer(kDirectFormat, back, GL_NEAREST, "atlas/back/direct");
    sumsBack = layer(kSumsFormat, back, GL_NEAREST, "atlas/back/sums");
    litBack = layer(kLitFormat, back, GL_LINEAR, "atlas/back/lit");
    const int sendersSize = bounceCount > 1 ? size : 1;
    senders = layer(kDirectFormat, sendersSize, GL_NEAREST, "atlas/bounce/senders");
    sendersBack = layer(kDirectFormat, std::min(back, sendersSize), GL_NEAREST,
            "atlas/bounce/back/senders");
    bounceSums.clear();
    bounceSumsBack.clear();
    for (int b = 1; b < bounceCount; ++b) {
        bounceSums.push_back(layer(kSumsFormat, size, GL_NEAREST, "atlas/bounce/sums"));
        bounceSumsBack.push_back(layer(kSumsFormat, back, GL_NEAREST, "atlas/bounce/back/sums"));
    }
}

std::vector<gl::MemoryItem> AtlasTextures::memoryFor(int resolution, bool backSides,
        int bounceCount) {
    const glm::ivec3 size(resolution, resolution, 1);
    const glm::ivec3 back = backSides ? size : glm::ivec3(1);
    std::vector<gl::MemoryItem> items = {{"atlas/direct", gl::textureBytes(kDirectFormat, size, 1)},
            {"atlas/normal", gl::textureBytes(kNormalFormat, size, 1)},
            {"atlas/position", gl::textureBytes(kPositionFormat, size, 1)},
            {"atlas/albedo", gl::textureBytes(kAlbedoFormat, size, 1)},
            {"atlas/sums", gl::textureBytes(kSumsFormat, size, 1)},
            {"atlas/lit", gl::textureBytes(kLitFormat, size, 1)},
            {"atlas/surface_mask", gl::textureBytes(kSurfaceMaskFormat, size, 1)},
            {"atlas/back/direct", gl::textureBytes(kDirectFormat, back, 1)},
            {"atlas/back/sums", gl::textureBytes(kSumsFormat, back, 1)},
            {"atlas/back/lit", gl::textureBytes(kLitFormat, back, 1)}};
    if (bounceCount > 1) {
        const std::size_t senders = gl::textureBytes(kDirectFormat, size, 1) +
                                    gl::textureBytes(kDirectFormat, back, 1);
        const std::size_t sumsPerBounce = gl::textureBytes(kSumsFormat, size, 1) +
                                          gl::textureBytes(kSumsFormat, back, 1);
        items.push_back({"atlas/bounce/senders", senders});
        items.push_back({"atlas/bounce/sums", std::size_t(bounceCount - 1) * sumsPerBounce});
    }
    return items;
}

bool AtlasTextures::needsBackSides(const scene::Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
            [](const scene::Material& material) { return material.doubleSided; });
}

} // namespace gi::atlas
