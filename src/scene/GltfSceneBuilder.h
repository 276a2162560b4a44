// Turns a parsed tinygltf::Model into a Scene, validating what the passes rely on. The work is
// spread by job: GltfSceneBuilder.cpp (extensions, samplers, cameras, lights, bounds),
// GltfMaterials.cpp (materials, textures, image decoding), GltfNodes.cpp (node hierarchy and
// placement), GltfPrimitives.cpp (mesh primitives) and GltfAnimations.cpp (animation channels).
// A failure leaves one "<file>: <element>: <what>" message; warnings have the same form.
#pragma once

#include "scene/GltfAccessorReader.h"
#include "scene/GltfFileAccess.h"
#include "scene/GltfLoader.h"
#include "scene/ImageDecoder.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace gi::scene::gltf {

class SceneBuilder {
public:
    SceneBuilder(const tinygltf::Model& model, const std::string& name, const FileAccess& access,
            const GltfLimits& limits, std::vector<std::string>& warnings)
        : mModel(model), mName(name), mAccess(access), mLimits(limits), mWarnings(warnings) {}

    bool build(Scene& scene, std::string& error);

private:
    struct PendingTexture {
        int sceneTexture;
        int image;
    };

    bool fail(const std::string& element, const std::string& what);
    // `elementAndWhat` is already "<element>: <what>" (from the accessor reader).
    bool failWith(const std::string& elementAndWhat);
    void warn(const std::string& element, const std::string& what);

    bool checkExtensions();
    bool checkSamplersAndTextures();
    bool checkCameras();
    bool checkLights();
    bool computeBounds();

    bool textureFor(const std::string& element, const char* slot,
            const tinygltf::TextureInfo& info, int& sceneTexture, int& texCoord);
    bool convertMaterials();
    bool decodeTextures();
    bool checkImagesBeforeDecoding(const std::vector<int>& images);
    bool decodeImages(const std::vector<int>& images, std::vector<DecodedImage>& decoded);

    bool checkNodes();
    bool failCycle(int member);
    bool localTransform(const tinygltf::Node& node, const std::string& element, glm::dmat4& out);
    bool selectRoots(std::vector<int>& roots);
    bool instantiate();
    bool placeMesh(int nodeIndex, const glm::dmat4& world);
    bool placeCamera(int nodeIndex, const glm::dmat4& world);
    bool placeLight(int nodeIndex, const glm::dmat4& world);

    bool primitiveFor(int mesh, int primitive, bool flipped, int& sceneIndex);
    bool reserveGeometry(const std::string& element, std::uint64_t vertices,
            std::uint64_t indices);
    bool readAttribute(const tinygltf::Primitive& source, const std::string& element,
            const char* name, std::initializer_list<int> allowedComponents, std::size_t count,
            AccessorFloats& out, bool& present);
    bool decodePrimitive(int mesh, int primitiveIndex, Primitive& out, bool& skipped);
    bool readVertices(const tinygltf::Primitive& source, const std::string& element,
            Primitive& out, std::vector<std::size_t>& degenerateNormals);
    bool readCorners(const tinygltf::Primitive& source, const std::string& element,
            std::size_t vertexCount, std::vector<std::uint32_t>& corners);
    void completeAttributes(const std::string& element,
            const std::vector<std::size_t>& degenerateNormals, Primitive& out);
    bool toTriangleList(const std::string& element, int mode,
            const std::vector<std::uint32_t>& corners, std::vector<std::uint32_t>& out);

    bool readAnimations();
    bool readChannel(const tinygltf::Animation& animation, const tinygltf::AnimationChannel& in,
            const std::string& element, AnimationChannel& out, bool& warnedWeights);
    bool readChannelKeys(const tinygltf::AnimationSampler& sampler,
            const tinygltf::AnimationChannel& in, const std::string& element,
            AnimationChannel& out);

    const tinygltf::Model& mModel;
    const std::string& mName;
    const FileAccess& mAccess;
    const GltfLimits& mLimits;
    std::vector<std::string>& mWarnings;
    std::string mError;
    Scene mScene;
    std::map<int, int> mTextureMap; // glTF texture -> Scene::textures index
    std::vector<PendingTexture> mPendingTextures;
    std::vector<int> mParent;
    std::vector<glm::dmat4> mLocal;
    std::map<std::tuple<int, int, bool>, int> mPrimitiveCache;
    std::uint64_t mVertexTotal = 0;
    std::uint64_t mIndexTotal = 0;
};

} // namespace gi::scene::gltf
