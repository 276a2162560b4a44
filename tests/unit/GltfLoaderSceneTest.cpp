// glTF loader tests of what the node tree places besides meshes (cameras, punctual lights),
// scene selection, bounds and warnings; and the real Sponza, when its files are present.
#include "GltfLoaderTestSupport.h"
#include "Sponza.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace gi::scene {
namespace {

using namespace loadertest;

// ---------------------------------------------------------------------------------------------
// Cameras and lights

TEST(GltfLoader, PlacesPerspectiveCamerasWithTheirNodeTransform) {
    GltfBuilder builder = triangleScene();
    builder.append("cameras", {{"type", "perspective"}, {"name", "main"},
                                      {"perspective", {{"yfov", 0.7}, {"znear", 0.1},
                                                              {"zfar", 100.0}}}});
    const float h = std::sqrt(0.5f);
    // Rotated 90 degrees about +Y (looks down world -X), scaled 3 (scale is dropped).
    const int node = builder.addNode({{"camera", 0}, {"translation", {1, 2, 3}},
            {"rotation", {0, h, 0, h}}, {"scale", {3, 3, 3}}});
    builder.doc()["scenes"][0]["nodes"].push_back(node);
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.cameras.size(), 1u);
    const Camera& camera = loaded.scene.cameras[0];
    EXPECT_EQ(camera.name, "main");
    EXPECT_FALSE(camera.isDefault);
    EXPECT_NEAR(camera.yfov, 0.7f, kEps);
    EXPECT_NEAR(camera.znear, 0.1f, kEps);
    EXPECT_NEAR(camera.zfar, 100.0f, 1e-3f);
    EXPECT_VEC3_NEAR(glm::vec3(camera.worldFromCamera[3]), glm::vec3(1, 2, 3), kEps);
    EXPECT_VEC3_NEAR(-glm::vec3(camera.worldFromCamera[2]), glm::vec3(-1, 0, 0), kEps);
    EXPECT_VEC3_NEAR(glm::vec3(camera.worldFromCamera[1]), glm::vec3(0, 1, 0), kEps);
}

TEST(GltfLoader, SkipsOrthographicCamerasWithAWarning) {
    GltfBuilder builder = triangleScene();
    builder.append("cameras", {{"type", "orthographic"},
                                      {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0},
                                                               {"znear", 0.1}, {"zfar", 10.0}}}});
    builder.doc()["scenes"][0]["nodes"].push_back(builder.addNode({{"camera", 0}}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_TRUE(loaded.scene.cameras.empty());
    EXPECT_TRUE(hasWarning(loaded, "cameras[0]: camera type 'orthographic' is not supported"))
            << allWarnings(loaded);
}

TEST(GltfLoader, PlacesPunctualLightsFromTheirNodes) {
    GltfBuilder builder = triangleScene();
    builder.doc()["extensionsUsed"] = {"KHR_lights_punctual"};
    builder.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {
            {{"type", "point"}, {"name", "bulb"}, {"color", {1.0, 0.5, 0.25}},
                    {"intensity", 20.0}, {"range", 8.0}},
            {{"type", "spot"}, {"intensity", 5.0},
                    {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
            {{"type", "directional"}, {"intensity", 3.0}},
    };
    const float h = std::sqrt(0.5f);
    auto lightNode = [](int light) {
        return json{{"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}};
    };
    json point = lightNode(0);
    point["translation"] = {1, 2, 3};
    json spot = lightNode(1);
    spot["translation"] = {0, 4, 0};
    spot["rotation"] = {-h, 0, 0, h}; // -90 degrees about X: local -Z becomes world -Y
    json sun = lightNode(2);
    sun["rotation"] = {0, h, 0, h}; // +90 degrees about Y: local -Z becomes world -X
    for (const json& node : {point, spot, sun}) {
        builder.doc()["scenes"][0]["nodes"].push_back(builder.addNode(node));
    }
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.lights.size(), 3u);
    const Light& p = loaded.scene.lights[0];
    EXPECT_EQ(p.type, LightType::Point);
    EXPECT_EQ(p.name, "bulb");
    EXPECT_VEC3_NEAR(p.position, glm::vec3(1, 2, 3), kEps);
    EXPECT_EQ(p.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(p.intensity, 20.0f);
    EXPECT_EQ(p.range, 8.0f);
    EXPECT_FALSE(p.isDefault);
    const Light& s = loaded.scene.lights[1];
    EXPECT_EQ(s.type, LightType::Spot);
    EXPECT_VEC3_NEAR(s.position, glm::vec3(0, 4, 0), kEps);
    EXPECT_VEC3_NEAR(s.direction, glm::vec3(0, -1, 0), kEps);
    EXPECT_EQ(s.color, glm::vec3(1.0f));
    EXPECT_NEAR(s.innerConeAngle, 0.2f, kEps);
    EXPECT_NEAR(s.outerConeAngle, 0.6f, kEps);
    EXPECT_EQ(s.range, 0.0f);
    const Light& d = loaded.scene.lights[2];
    EXPECT_EQ(d.type, LightType::Directional);
    EXPECT_VEC3_NEAR(d.direction, glm::vec3(-1, 0, 0), kEps);
    EXPECT_EQ(d.intensity, 3.0f);
}

// ---------------------------------------------------------------------------------------------
// Scenes and bounds

TEST(GltfLoader, UsesTheDefaultSceneOrSceneZeroOrAllRoots) {
    GltfBuilder builder;
    const int mesh = builder.addTriangleMesh(kTriangle, {0, 1, 2});
    const int a = builder.addNode({{"mesh", mesh}, {"translation", {10, 0, 0}}});
    const int b = builder.addNode({{"mesh", mesh}, {"translation", {20, 0, 0}}});
    const int c = builder.addNode({{"mesh", mesh}, {"translation", {30, 0, 0}}});
    builder.addScene({a});
    builder.addScene({b, c});
    {
        SCOPED_TRACE("scene: 1");
        builder.doc()["scene"] = 1;
        const Loaded loaded = loadBuilt(builder);
        ASSERT_TRUE(loaded.ok) << loaded.error;
        ASSERT_EQ(loaded.scene.instances.size(), 2u);
        EXPECT_EQ(loaded.scene.instances[0].node, b);
        EXPECT_EQ(loaded.scene.instances[1].node, c);
    }
    {
        SCOPED_TRACE("no scene: scene 0");
        builder.doc().erase("scene");
        const Loaded loaded = loadBuilt(builder);
        ASSERT_TRUE(loaded.ok) << loaded.error;
        ASSERT_EQ(loaded.scene.instances.size(), 1u);
        EXPECT_EQ(loaded.scene.instances[0].node, a);
    }
    {
        SCOPED_TRACE("no scenes: every root node");
        builder.doc().erase("scenes");
        const Loaded loaded = loadBuilt(builder);
        ASSERT_TRUE(loaded.ok) << loaded.error;
        EXPECT_EQ(loaded.scene.instances.size(), 3u);
    }
}

TEST(GltfLoader, ComputesWorldBounds) {
    GltfBuilder builder;
    const int mesh = builder.addTriangleMesh(kTriangle, {0, 1, 2});
    builder.addScene({builder.addNode({{"mesh", mesh}, {"translation", {10, 0, 0}},
                              {"scale", {2, 3, 1}}}),
            builder.addNode({{"mesh", mesh}, {"translation", {0, 0, -5}}})});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_VEC3_NEAR(loaded.scene.bounds.min, glm::vec3(0, 0, -5), kEps);
    EXPECT_VEC3_NEAR(loaded.scene.bounds.max, glm::vec3(12, 3, 0), kEps);
    EXPECT_VEC3_NEAR(loaded.scene.primitives[0].localBounds.max, glm::vec3(1, 1, 0), kEps);
}

TEST(GltfLoader, SceneWithoutTrianglesIsValidWithEmptyBounds) {
    GltfBuilder builder;
    builder.addScene({builder.addNode({{"name", "empty"}})});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.triangleCount(), 0u);
    EXPECT_TRUE(loaded.scene.bounds.empty());
}

TEST(GltfLoader, WarnsAboutUnsupportedExtensionsThatAreOnlyUsed) {
    GltfBuilder builder = triangleScene();
    builder.doc()["extensionsUsed"] = {"KHR_texture_transform", "KHR_lights_punctual"};
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_TRUE(hasWarning(loaded, "extensionsUsed: ignoring unsupported KHR_texture_transform"))
            << allWarnings(loaded);
}

// A missing image no material samples does not stop the scene from rendering correctly.
TEST(GltfLoader, PassesTinygltfWarningsThrough) {
    GltfBuilder builder = triangleScene();
    builder.append("images", {{"uri", "unused-and-missing.png"}});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_FALSE(loaded.warnings.empty());
    for (const std::string& warning : loaded.warnings) {
        EXPECT_NE(warning.find("scene.gltf: "), std::string::npos) << warning;
        EXPECT_EQ(warning.find('\n'), std::string::npos) << warning;
    }
}

TEST(GltfLoader, DropsATrailingPartialTriangleWithAWarning) {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                               {0, 1, 2, 3, 2}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[0]: 5 triangle corners is not a "
                                   "multiple of 3; the last 2 are dropped"))
            << allWarnings(loaded);
}

// ---------------------------------------------------------------------------------------------
// The real Sponza, when present (support/Sponza.h: never committed, read from beside the
// clone or $VOXATLAS_SPONZA).

TEST(GltfLoaderSponza, LoadsWithAllTrianglesAndTextures) {
    VOXATLAS_SPONZA_OR_SKIP(path);
    const auto start = std::chrono::steady_clock::now();
    const Loaded loaded = loadFile(path);
    const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.triangleCount(), 230831u);
    EXPECT_EQ(loaded.scene.textures.size(), 23u);
    EXPECT_EQ(loaded.scene.materials.size(), 24u);
    for (const Texture& texture : loaded.scene.textures) {
        EXPECT_EQ(texture.rgba8.size(), std::size_t(texture.width) * texture.height * 4);
    }
    std::cout << "Sponza: " << loaded.scene.triangleCount() << " triangles, "
              << loaded.scene.textures.size() << " textures, loaded in " << seconds << " s\n";
}

} // namespace
} // namespace gi::scene
