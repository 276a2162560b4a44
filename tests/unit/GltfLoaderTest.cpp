// glTF loader tests: one small file per feature and one per rejected input, each written by
// the test itself (GltfTestFiles) so the input sits next to its assertions. Error tests check
// the one-line "<file>: <element>: <what>" form the command line passes on to users.
#include "GltfLoaderTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace gi::scene {
namespace {

using namespace loadertest;

// ---------------------------------------------------------------------------------------------
// Containers and buffers

TEST(GltfLoader, LoadsGltfWithExternalBuffer) {
    const Loaded loaded = loadBuilt(triangleScene(), BufferStorage::External);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Scene& scene = loaded.scene;
    ASSERT_EQ(scene.primitives.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.primitives[0].positions, kTriangle);
    EXPECT_EQ(scene.primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(scene.primitives[0].material, -1);
    EXPECT_TRUE(scene.primitives[0].texcoords0.empty());
    EXPECT_TRUE(scene.primitives[0].colors.empty());
    EXPECT_NE(scene.sourcePath.find("scene.gltf"), std::string::npos);
}

TEST(GltfLoader, LoadsGltfWithEmbeddedBase64Buffer) {
    const Loaded loaded = loadBuilt(triangleScene(), BufferStorage::Embedded);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.triangleCount(), 1u);
    EXPECT_EQ(loaded.scene.primitives[0].positions, kTriangle);
}

TEST(GltfLoader, LoadsGlbWithBinChunk) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const Loaded loaded = loadFile(triangleScene().writeGlb(dir, "scene"));
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.triangleCount(), 1u);
    EXPECT_EQ(loaded.scene.primitives[0].positions, kTriangle);
}

TEST(GltfLoader, RecognisesGlbByMagicNotExtension) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::vector<std::uint8_t> glb = triangleScene().glb();
    gi::test::writeBytes(dir / "binary.gltf", glb.data(), glb.size());
    const Loaded loaded = loadFile((dir / "binary.gltf").string());
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.triangleCount(), 1u);
}

TEST(GltfLoader, LoadsFromMemory) {
    const std::vector<std::uint8_t> glb = triangleScene().glb();
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(loadGltfFromMemory(glb.data(), glb.size(), "memory.glb", "", scene, error,
            warnings))
            << error;
    EXPECT_EQ(scene.triangleCount(), 1u);

    const std::string text = triangleScene().gltfText(BufferStorage::Embedded, "");
    Scene fromText;
    ASSERT_TRUE(loadGltfFromMemory(reinterpret_cast<const std::uint8_t*>(text.data()),
            text.size(), "memory.gltf", "", fromText, error, warnings))
            << error;
    EXPECT_EQ(fromText.triangleCount(), 1u);
}

TEST(GltfLoader, MemoryLoadWithoutBaseDirOpensNoFiles) {
    const std::string text = triangleScene().gltfText(BufferStorage::External, "scene.bin");
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_FALSE(loadGltfFromMemory(reinterpret_cast<const std::uint8_t*>(text.data()),
            text.size(), "memory.gltf", "", scene, error, warnings));
    EXPECT_EQ(error.rfind("memory.gltf: buffers[0]: ", 0), 0u) << error;
    EXPECT_NE(error.find("external files are disabled"), std::string::npos) << error;
}

// ---------------------------------------------------------------------------------------------
// Node hierarchy and transforms

TEST(GltfLoader, ComposesTrsAndMatrixTransformsDownTheHierarchy) {
    GltfBuilder builder;
    const int mesh = builder.addTriangleMesh(kTriangle, {0, 1, 2});
    // Child: column-major matrix translating by (0, 0, 5).
    const int child = builder.addNode({{"mesh", mesh},
            {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}});
    // Parent: translate (10, 0, 0), rotate 90 degrees about +Z, scale 2.
    const float h = std::sqrt(0.5f);
    const int parent = builder.addNode({{"children", {child}}, {"translation", {10, 0, 0}},
            {"rotation", {0, 0, h, h}}, {"scale", {2, 2, 2}}});
    builder.addScene({parent});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.instances.size(), 1u);
    const Instance& instance = loaded.scene.instances[0];
    EXPECT_EQ(instance.node, child);
    EXPECT_FALSE(instance.flipWinding);
    // (1,0,0) -> child (1,0,5) -> scale (2,0,10) -> rotate (0,2,10) -> translate (10,2,10).
    EXPECT_VEC3_NEAR(worldPosition(loaded.scene, instance, 1), glm::vec3(10, 2, 10), kEps);
    EXPECT_VEC3_NEAR(worldPosition(loaded.scene, instance, 2), glm::vec3(8, 0, 10), kEps);
}

TEST(GltfLoader, NegativeScaleReversesTrianglesSoWorldWindingStaysCounterClockwise) {
    GltfBuilder builder;
    const int mesh = builder.addTriangleMesh(kTriangle, {0, 1, 2});
    const int plain = builder.addNode({{"mesh", mesh}});
    const int mirrored = builder.addNode({{"mesh", mesh}, {"scale", {-1, 1, 1}}});
    builder.addScene({plain, mirrored});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Scene& scene = loaded.scene;
    ASSERT_EQ(scene.instances.size(), 2u);
    ASSERT_EQ(scene.primitives.size(), 2u) << "a mirrored instance needs its own reversed copy";
    EXPECT_FALSE(scene.instances[0].flipWinding);
    EXPECT_TRUE(scene.instances[1].flipWinding);
    EXPECT_NE(scene.instances[0].primitive, scene.instances[1].primitive);
    for (const Instance& instance : scene.instances) {
        const Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        const glm::vec3 a = worldPosition(scene, instance, primitive.indices[0]);
        const glm::vec3 b = worldPosition(scene, instance, primitive.indices[1]);
        const glm::vec3 c = worldPosition(scene, instance, primitive.indices[2]);
        const glm::mat3 normalMatrix =
                glm::transpose(glm::inverse(glm::mat3(instance.worldFromLocal)));
        const glm::vec3 n = normalMatrix * primitive.normals[primitive.indices[0]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), n), 0.0f)
                << "instance of node " << instance.node << " is not counter-clockwise";
    }
}

TEST(GltfLoader, LoadsEveryPrimitiveOfEveryMesh) {
    GltfBuilder builder;
    const int p0 = builder.addVec3(kTriangle);
    const int p1 = builder.addVec3({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
    const int i1 = builder.addIndices({0, 1, 2, 2, 1, 3});
    const int meshA = builder.addMesh(json::array({{{"attributes", {{"POSITION", p0}}}},
            {{"attributes", {{"POSITION", p1}}}, {"indices", i1}}}));
    const int meshB = builder.addTriangleMesh({{5, 0, 0}, {6, 0, 0}, {5, 1, 0}}, {});
    const int a = builder.addNode({{"mesh", meshA}});
    const int b = builder.addNode({{"mesh", meshB}});
    builder.addScene({a, b});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives.size(), 3u);
    EXPECT_EQ(loaded.scene.instances.size(), 3u);
    EXPECT_EQ(loaded.scene.triangleCount(), 4u);
}

TEST(GltfLoader, ConvertsTriangleStripToList) {
    GltfBuilder builder;
    const int positions = builder.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    placeMesh(builder, builder.addMesh(json::array(
                               {{{"attributes", {{"POSITION", positions}}}, {"mode", 5}}})));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    // glTF 2.0 section 3.7.2.1: triangle i of a strip is (i, i+1+i%2, i+2-i%2).
    EXPECT_EQ(loaded.scene.primitives[0].indices,
            (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
}

TEST(GltfLoader, ConvertsTriangleFanToList) {
    GltfBuilder builder;
    const int positions = builder.addVec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const int indices = builder.addIndices({0, 1, 2, 3});
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"POSITION", positions}}},
                               {"indices", indices}, {"mode", 6}}})));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    // glTF 2.0 section 3.7.2.1: triangle i of a fan is (i+1, i+2, 0).
    EXPECT_EQ(loaded.scene.primitives[0].indices,
            (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}));
}

TEST(GltfLoader, SkipsPointAndLinePrimitivesWithWarnings) {
    GltfBuilder builder;
    const int positions = builder.addVec3(kTriangle);
    placeMesh(builder, builder.addMesh(json::array({
                               {{"attributes", {{"POSITION", positions}}}, {"mode", 0}},
                               {{"attributes", {{"POSITION", positions}}}, {"mode", 1}},
                               {{"attributes", {{"POSITION", positions}}}, {"mode", 3}},
                               {{"attributes", {{"POSITION", positions}}}},
                       })));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives.size(), 1u);
    EXPECT_EQ(loaded.scene.triangleCount(), 1u);
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[0]: mode POINTS")) << allWarnings(loaded);
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[1]: mode LINES")) << allWarnings(loaded);
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[2]: mode LINE_STRIP"))
            << allWarnings(loaded);
}

TEST(GltfLoader, SkipsPrimitivesWithoutTrianglesWithAWarning) {
    GltfBuilder builder;
    const int empty = builder.addAccessor(builder.addBufferView(std::vector<float>{0}),
            gi::test::kGltfFloat, 0, "VEC3");
    const int two = builder.addVec3({{0, 0, 0}, {1, 0, 0}});
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"POSITION", empty}}}},
                               {{"attributes", {{"POSITION", two}}}}})));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_TRUE(loaded.scene.primitives.empty());
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[0]: has no triangles; skipped"))
            << allWarnings(loaded);
    EXPECT_TRUE(hasWarning(loaded, "meshes[0].primitives[1]: has no triangles; skipped"))
            << allWarnings(loaded);
}

TEST(GltfLoader, NonIndexedPrimitiveUsesVerticesInOrder) {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                                       {1, 1, 0}, {0, 1, 0}},
                               {}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].indices,
            (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(GltfLoader, ReadsAllIndexComponentTypes) {
    for (int type : {gi::test::kGltfUnsignedByte, gi::test::kGltfUnsignedShort,
                 gi::test::kGltfUnsignedInt}) {
        SCOPED_TRACE("componentType " + std::to_string(type));
        GltfBuilder builder;
        const int positions = builder.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
        const int indices = builder.addIndices({0, 1, 2, 2, 1, 3}, type);
        placeMesh(builder, builder.addMesh(json::array(
                                   {{{"attributes", {{"POSITION", positions}}},
                                           {"indices", indices}}})));
        const Loaded loaded = loadBuilt(builder);
        ASSERT_TRUE(loaded.ok) << loaded.error;
        EXPECT_EQ(loaded.scene.primitives[0].indices,
                (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
    }
}

// ---------------------------------------------------------------------------------------------

} // namespace
} // namespace gi::scene
