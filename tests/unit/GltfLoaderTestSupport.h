// Shared by the glTF loader tests (GltfLoader*Test.cpp): loading files the tests write with
// GltfTestFiles, and checking the one-line "<file>: <element>: <what>" errors and the warnings.
#pragma once

#include "GltfTestFiles.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gi::scene::loadertest {

using gi::test::BufferStorage;
using gi::test::GltfBuilder;
using nlohmann::json;

// Float comparisons of values that went through float arithmetic once or twice.
inline constexpr float kEps = 1e-5f;

inline const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

struct Loaded {
    bool ok = false;
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
};

inline Loaded loadFile(const std::string& path, const GltfLimits& limits = {}) {
    Loaded result;
    result.ok = loadGltf(path, result.scene, result.error, result.warnings, limits);
    return result;
}

inline std::string testName() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::string(info->test_suite_name()) + "." + info->name();
}

// Writes the builder as <test dir>/scene.gltf (or .glb) and loads it.
inline Loaded loadBuilt(const GltfBuilder& builder, BufferStorage storage = BufferStorage::External,
        const GltfLimits& limits = {}) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    return loadFile(builder.writeGltf(dir, "scene", storage), limits);
}

// One node placing `mesh`, in scene 0.
inline void placeMesh(GltfBuilder& builder, int mesh, json node = json::object()) {
    node["mesh"] = mesh;
    builder.addScene({builder.addNode(node)});
}

inline GltfBuilder triangleScene() {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}));
    return builder;
}

inline bool hasWarning(const Loaded& loaded, const std::string& text) {
    for (const std::string& warning : loaded.warnings) {
        if (warning.find(text) != std::string::npos) return true;
    }
    return false;
}

inline std::string allWarnings(const Loaded& loaded) {
    std::string out;
    for (const std::string& warning : loaded.warnings) out += warning + "\n";
    return out;
}

// Asserts a failed load whose one-line message is "<path>: <element>: ..." and contains `what`.
inline void expectError(const Loaded& loaded, const std::string& path, const std::string& element,
        const std::string& what) {
    ASSERT_FALSE(loaded.ok) << "loaded although an error was expected";
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
    EXPECT_EQ(loaded.error.rfind(path + ": " + element + ": ", 0), 0u)
            << "expected \"" << path << ": " << element << ": ...\", got: " << loaded.error;
    EXPECT_NE(loaded.error.find(what), std::string::npos)
            << "expected to contain \"" << what << "\", got: " << loaded.error;
}

// Writes the builder, loads it, expects an error naming `element`.
inline void expectBuiltError(const GltfBuilder& builder, const std::string& element,
        const std::string& what, BufferStorage storage = BufferStorage::External) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = builder.writeGltf(dir, "scene", storage);
    expectError(loadFile(path), path, element, what);
}

inline glm::vec3 worldPosition(const Scene& scene, const Instance& instance, std::uint32_t vertex) {
    const Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
    return glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[vertex], 1.0f));
}

#define EXPECT_VEC3_NEAR(a, b, eps)                                                            \
    do {                                                                                       \
        const glm::vec3 va_ = (a), vb_ = (b);                                                  \
        EXPECT_NEAR(va_.x, vb_.x, eps);                                                        \
        EXPECT_NEAR(va_.y, vb_.y, eps);                                                        \
        EXPECT_NEAR(va_.z, vb_.z, eps);                                                        \
    } while (0)

// A 2x2 image of `channels` channels: pixel i has every channel = 60 * (i + 1) + channel.
inline std::vector<std::uint8_t> testPixels(int channels) {
    std::vector<std::uint8_t> pixels;
    for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < channels; ++c) pixels.push_back(std::uint8_t(60 * (i + 1) + c));
    }
    return pixels;
}

// One material per image, each a base-colour texture of a triangle mesh; images embedded as
// data URIs.
inline GltfBuilder texturedScene(const std::vector<std::vector<std::uint8_t>>& images,
        const char* mime = "image/png") {
    GltfBuilder builder;
    const int uv = builder.addVec2({{0, 0}, {1, 0}, {0, 1}});
    json primitives = json::array();
    const int positions = builder.addVec3(kTriangle);
    for (std::size_t i = 0; i < images.size(); ++i) {
        builder.append("images", {{"uri", std::string("data:") + mime + ";base64," +
                                                  gi::test::base64Encode(images[i])}});
        builder.append("textures", {{"source", i}});
        builder.append("materials",
                {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        primitives.push_back({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uv}}},
                {"material", i}});
    }
    placeMesh(builder, builder.addMesh(primitives));
    return builder;
}

} // namespace gi::scene::loadertest
