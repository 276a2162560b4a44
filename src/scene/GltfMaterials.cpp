// SceneBuilder's materials and textures: factors and alpha modes checked, each texture slot
// resolved to a Scene texture, and every image those textures need decoded once, in parallel.
#include "scene/GltfSceneBuilder.h"

#include "scene/GltfMessages.h"

#include <algorithm>
#include <atomic>
#include <new>
#include <system_error>
#include <thread>

namespace gi::scene::gltf {
namespace {

// "'file.png': " for external images, so messages name the file; empty otherwise.
std::string imageSource(const tinygltf::Image& image) {
    return !image.uri.empty() && !isDataUri(image.uri) ? "'" + image.uri + "': " : "";
}

} // namespace

// Scene texture for a material's texture slot; -1 when the slot is empty or ignored.
bool SceneBuilder::textureFor(const std::string& element, const char* slot,
        const tinygltf::TextureInfo& info, int& sceneTexture, int& texCoord) {
    sceneTexture = -1;
    texCoord = 0;
    if (info.index == -1) return true;
    if (info.index < 0 || std::size_t(info.index) >= mModel.textures.size()) {
        return fail(element, doesNotExist((std::string(slot) + ".index").c_str(), info.index,
                                     mModel.textures.size(), "textures"));
    }
    if (info.texCoord < 0) {
        return fail(element, std::string(slot) + ".texCoord " +
                                     std::to_string(info.texCoord) + " is negative");
    }
    if (info.texCoord > 1) {
        warn(element, std::string(slot) + " uses TEXCOORD_" +
                              std::to_string(info.texCoord) +
                              "; only TEXCOORD_0 and TEXCOORD_1 are loaded, texture ignored");
        return true;
    }
    const tinygltf::Texture& texture = mModel.textures[std::size_t(info.index)];
    if (texture.source < 0) {
        warn(indexed("textures", info.index), "has no source image; texture ignored");
        return true;
    }
    texCoord = info.texCoord;
    auto found = mTextureMap.find(info.index);
    if (found != mTextureMap.end()) {
        sceneTexture = found->second;
        return true;
    }
    Texture out;
    const tinygltf::Image& image = mModel.images[std::size_t(texture.source)];
    out.name = !texture.name.empty() ? texture.name
               : !image.name.empty() ? image.name
               : !image.uri.empty() && !isDataUri(image.uri)
                       ? image.uri
                       : indexed("textures", info.index);
    out.srgb = true;
    if (texture.sampler >= 0) {
        out.wrapS = mModel.samplers[std::size_t(texture.sampler)].wrapS;
        out.wrapT = mModel.samplers[std::size_t(texture.sampler)].wrapT;
    }
    sceneTexture = int(mScene.textures.size());
    mScene.textures.push_back(std::move(out));
    mTextureMap[info.index] = sceneTexture;
    mPendingTextures.push_back({sceneTexture, texture.source});
    return true;
}

bool SceneBuilder::convertMaterials() {
    for (std::size_t i = 0; i < mModel.materials.size(); ++i) {
        const tinygltf::Material& source = mModel.materials[i];
        const std::string element = indexed("materials", long(i));
        Material material;
        material.name = source.name.empty() ? element : source.name;
        const std::vector<double>& base = source.pbrMetallicRoughness.baseColorFactor;
        if (base.size() != 4 || !allFinite(base) ||
                std::any_of(base.begin(), base.end(), [](double v) { return v < 0.0; })) {
            return fail(element, "pbrMetallicRoughness.baseColorFactor must be 4 finite "
                                 "numbers >= 0");
        }
        material.baseColorFactor = glm::vec4(base[0], base[1], base[2], base[3]);
        const std::vector<double>& emissive = source.emissiveFactor;
        if (emissive.size() != 3 || !allFinite(emissive) ||
                std::any_of(emissive.begin(), emissive.end(),
                        [](double v) { return v < 0.0; })) {
            return fail(element, "emissiveFactor must be 3 finite numbers >= 0");
        }
        material.emissiveFactor = glm::vec3(emissive[0], emissive[1], emissive[2]);
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        if (!finite(pbr.metallicFactor) || pbr.metallicFactor < 0.0 || pbr.metallicFactor > 1.0 ||
                !finite(pbr.roughnessFactor) || pbr.roughnessFactor < 0.0 ||
                pbr.roughnessFactor > 1.0) {
            return fail(element, "pbrMetallicRoughness.metallicFactor and roughnessFactor must "
                                 "be finite numbers in [0, 1]");
        }
        material.metallicFactor = float(pbr.metallicFactor);
        material.roughnessFactor = float(pbr.roughnessFactor);
        if (pbr.metallicRoughnessTexture.index >= 0) {
            warn(element, "pbrMetallicRoughness.metallicRoughnessTexture is not supported; the "
                          "factors alone are used");
        }
        auto strength = source.extensions.find("KHR_materials_emissive_strength");
        if (strength != source.extensions.end()) {
            const tinygltf::Value& ext = strength->second;
            double value = 1.0;
            if (ext.IsObject() && ext.Has("emissiveStrength")) {
                const tinygltf::Value& v = ext.Get("emissiveStrength");
                value = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
            }
            if (!finite(value) || value < 0.0) {
                return fail(element, "KHR_materials_emissive_strength.emissiveStrength is "
                                     "not a finite number >= 0");
            }
            material.emissiveFactor *= float(value);
            if (!finite(glm::length(glm::dvec3(material.emissiveFactor)))) {
                return fail(element, "emissiveFactor x emissiveStrength is not finite");
            }
        }
        if (source.alphaMode == "OPAQUE") {
            material.alphaMode = AlphaMode::Opaque;
        } else if (source.alphaMode == "MASK") {
            material.alphaMode = AlphaMode::Mask;
        } else if (source.alphaMode == "BLEND") {
            material.alphaMode = AlphaMode::Blend;
        } else {
            return fail(element, "alphaMode '" + source.alphaMode +
                                         "' is not OPAQUE, MASK or BLEND");
        }
        if (!finite(source.alphaCutoff) || source.alphaCutoff < 0.0) {
            return fail(element, "alphaCutoff " + std::to_string(source.alphaCutoff) +
                                         " is not a finite number >= 0");
        }
        material.alphaCutoff = float(source.alphaCutoff);
        material.doubleSided = source.doubleSided;
        if (!textureFor(element, "pbrMetallicRoughness.baseColorTexture",
                    source.pbrMetallicRoughness.baseColorTexture, material.baseColorTexture,
                    material.baseColorTexCoord) ||
                !textureFor(element, "emissiveTexture", source.emissiveTexture,
                        material.emissiveTexture, material.emissiveTexCoord)) {
            return false;
        }
        mScene.materials.push_back(std::move(material));
    }
    return true;
}

// Decodes every image a scene texture needs, each once, on up to one thread per core.
bool SceneBuilder::decodeTextures() {
    std::vector<int> images;
    for (const PendingTexture& pending : mPendingTextures) images.push_back(pending.image);
    std::sort(images.begin(), images.end());
    images.erase(std::unique(images.begin(), images.end()), images.end());
    std::vector<DecodedImage> decoded(images.size());
    if (!checkImagesBeforeDecoding(images) || !decodeImages(images, decoded)) return false;
    std::vector<int> usesLeft(images.size(), 0);
    auto slot = [&](int image) {
        return std::size_t(std::lower_bound(images.begin(), images.end(), image) -
                           images.begin());
    };
    for (const PendingTexture& pending : mPendingTextures) ++usesLeft[slot(pending.image)];
    for (const PendingTexture& pending : mPendingTextures) {
        const std::size_t k = slot(pending.image);
        Texture& texture = mScene.textures[std::size_t(pending.sceneTexture)];
        texture.width = decoded[k].width;
        texture.height = decoded[k].height;
        if (--usesLeft[k] == 0) {
            texture.rgba8 = std::move(decoded[k].rgba8);
        } else {
            texture.rgba8 = decoded[k].rgba8;
        }
    }
    return true;
}

// Every image has bytes, and the headers' sizes stay within the limit in total.
bool SceneBuilder::checkImagesBeforeDecoding(const std::vector<int>& images) {
    for (int index : images) {
        const tinygltf::Image& image = mModel.images[std::size_t(index)];
        if (image.image.empty()) {
            const std::string element = indexed("images", index);
            if (!image.uri.empty() && !isDataUri(image.uri)) {
                const std::string problem = externalFileProblem(mAccess, image.uri, 0, false);
                return fail(element, problem.empty() ? "cannot read '" + image.uri + "'"
                                                     : problem);
            }
            return fail(element, "has no image data");
        }
    }
    // Headers first: refuse images too large in total before decoding any of them.
    std::uint64_t totalPixels = 0;
    for (int index : images) {
        const tinygltf::Image& image = mModel.images[std::size_t(index)];
        int width = 0, height = 0;
        std::string error;
        if (!readImageSize(image.image.data(), image.image.size(), width, height, error)) {
            return fail(indexed("images", index), imageSource(image) + error);
        }
        totalPixels += std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0));
        if (totalPixels > mLimits.maxTotalImagePixels) {
            return fail(indexed("images", index),
                    "the scene's images exceed the loader's limit of " +
                            std::to_string(mLimits.maxTotalImagePixels) + " pixels in total");
        }
    }
    return true;
}

bool SceneBuilder::decodeImages(
        const std::vector<int>& images, std::vector<DecodedImage>& decoded) {
    std::vector<std::string> errors(images.size());
    std::atomic<std::size_t> next{0};
    auto work = [&]() {
        for (std::size_t k = next++; k < images.size(); k = next++) {
            try {
                const tinygltf::Image& image = mModel.images[std::size_t(images[k])];
                if (!decodeImageRgba8(image.image.data(), image.image.size(),
                            mLimits.maxImagePixels, decoded[k], errors[k])) {
                    if (errors[k].empty()) errors[k] = "cannot decode the image";
                }
            } catch (const std::bad_alloc&) {
                errors[k] = "out of memory while decoding the image";
            } catch (...) {
                errors[k] = "cannot decode the image";
            }
        }
    };
    const std::size_t threadCount = std::min<std::size_t>(
            images.size(), std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    std::vector<std::thread> threads;
    for (std::size_t t = 1; t < threadCount; ++t) {
        try {
            threads.emplace_back(work);
        } catch (const std::system_error&) {
            break;
        }
    }
    work();
    for (std::thread& thread : threads) thread.join();

    for (std::size_t k = 0; k < images.size(); ++k) {
        if (!errors[k].empty()) {
            const tinygltf::Image& image = mModel.images[std::size_t(images[k])];
            return fail(indexed("images", images[k]), imageSource(image) + errors[k]);
        }
    }
    return true;
}

} // namespace gi::scene::gltf
