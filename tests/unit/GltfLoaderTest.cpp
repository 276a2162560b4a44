// glTF loader tests: one small file per feature and one per rejected input, each written by
// the test itself (GltfTestFiles) so the input sits next to its assertions. Error tests check
// the one-line "<file>: <element>: <what>" form the command line passes on to users.
#include "GltfTestFiles.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

namespace gi::scene {
namespace {

using gi::test::BufferStorage;
using gi::test::GltfBuilder;
using nlohmann::json;

// Float comparisons of values that went through float arithmetic once or twice.
constexpr float kEps = 1e-5f;

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

struct Loaded {
    bool ok = false;
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
};

Loaded loadFile(const std::string& path, const GltfLimits& limits = {}) {
    Loaded result;
    result.ok = loadGltf(path, result.scene, result.error, result.warnings, limits);
    return result;
}

std::string testName() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::string(info->test_suite_name()) + "." + info->name();
}

// Writes the builder as <test dir>/scene.gltf (or .glb) and loads it.
Loaded loadBuilt(const GltfBuilder& builder, BufferStorage storage = BufferStorage::External,
        const GltfLimits& limits = {}) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    return loadFile(builder.writeGltf(dir, "scene", storage), limits);
}

// One node placing `mesh`, in scene 0.
void placeMesh(GltfBuilder& builder, int mesh, json node = json::object()) {
    node["mesh"] = mesh;
    builder.addScene({builder.addNode(node)});
}

GltfBuilder triangleScene() {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}));
    return builder;
}

bool hasWarning(const Loaded& loaded, const std::string& text) {
    for (const std::string& warning : loaded.warnings) {
        if (warning.find(text) != std::string::npos) return true;
    }
    return false;
}

std::string allWarnings(const Loaded& loaded) {
    std::string out;
    for (const std::string& warning : loaded.warnings) out += warning + "\n";
    return out;
}

// Asserts a failed load whose one-line message is "<path>: <element>: ..." and contains `what`.
void expectError(const Loaded& loaded, const std::string& path, const std::string& element,
        const std::string& what) {
    ASSERT_FALSE(loaded.ok) << "loaded although an error was expected";
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
    EXPECT_EQ(loaded.error.rfind(path + ": " + element + ": ", 0), 0u)
            << "expected \"" << path << ": " << element << ": ...\", got: " << loaded.error;
    EXPECT_NE(loaded.error.find(what), std::string::npos)
            << "expected to contain \"" << what << "\", got: " << loaded.error;
}

// Writes the builder, loads it, expects an error naming `element`.
void expectBuiltError(const GltfBuilder& builder, const std::string& element,
        const std::string& what, BufferStorage storage = BufferStorage::External) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = builder.writeGltf(dir, "scene", storage);
    expectError(loadFile(path), path, element, what);
}

glm::vec3 worldPosition(const Scene& scene, const Instance& instance, std::uint32_t vertex) {
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
// Accessors

// POSITION as three floats; `attribute` holds `bytes` for 3 vertices of the given layout.
Loaded loadWithAttribute(const std::string& name, const std::vector<std::uint8_t>& bytes,
        int componentType, const std::string& type, bool normalized) {
    GltfBuilder builder;
    const int view = builder.addBufferView(bytes);
    const int accessor = builder.addAccessor(view, componentType, 3, type, 0, normalized);
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{name, accessor}}));
    return loadBuilt(builder);
}

template <class T> std::vector<std::uint8_t> bytesOf(const std::vector<T>& values) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
    return {p, p + values.size() * sizeof(T)};
}

TEST(GltfLoader, ConvertsNormalizedAndIntegerComponentTypes) {
    {
        SCOPED_TRACE("TEXCOORD_0 normalized UNSIGNED_BYTE");
        const Loaded l = loadWithAttribute("TEXCOORD_0",
                {0, 255, 51, 102, 255, 0, 0, 0}, gi::test::kGltfUnsignedByte, "VEC2", true);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_NEAR(l.scene.primitives[0].texcoords0[0].y, 1.0f, kEps);
        EXPECT_NEAR(l.scene.primitives[0].texcoords0[1].x, 0.2f, kEps);
        EXPECT_NEAR(l.scene.primitives[0].texcoords0[1].y, 0.4f, kEps);
    }
    {
        SCOPED_TRACE("TEXCOORD_0 normalized UNSIGNED_SHORT");
        const Loaded l = loadWithAttribute("TEXCOORD_0",
                bytesOf(std::vector<std::uint16_t>{0, 65535, 13107, 0, 65535, 65535}),
                gi::test::kGltfUnsignedShort, "VEC2", true);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_NEAR(l.scene.primitives[0].texcoords0[0].y, 1.0f, kEps);
        EXPECT_NEAR(l.scene.primitives[0].texcoords0[1].x, 0.2f, kEps);
    }
    {
        SCOPED_TRACE("TEXCOORD_0 normalized BYTE and SHORT clamp -128 / -32768 to -1");
        const Loaded l = loadWithAttribute("TEXCOORD_0",
                bytesOf(std::vector<std::int8_t>{-128, 127, -127, 0, 0, 0}),
                gi::test::kGltfByte, "VEC2", true);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_EQ(l.scene.primitives[0].texcoords0[0], glm::vec2(-1.0f, 1.0f));
        EXPECT_EQ(l.scene.primitives[0].texcoords0[1].x, -1.0f);
        const Loaded s = loadWithAttribute("TEXCOORD_0",
                bytesOf(std::vector<std::int16_t>{-32768, 32767, 0, 0, 0, 0}),
                gi::test::kGltfShort, "VEC2", true);
        ASSERT_TRUE(s.ok) << s.error;
        EXPECT_EQ(s.scene.primitives[0].texcoords0[0], glm::vec2(-1.0f, 1.0f));
    }
    {
        SCOPED_TRACE("TEXCOORD_0 non-normalized UNSIGNED_SHORT keeps integer values");
        const Loaded l = loadWithAttribute("TEXCOORD_0",
                bytesOf(std::vector<std::uint16_t>{3, 7, 0, 0, 65535, 1}),
                gi::test::kGltfUnsignedShort, "VEC2", false);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_EQ(l.scene.primitives[0].texcoords0[0], glm::vec2(3.0f, 7.0f));
        EXPECT_EQ(l.scene.primitives[0].texcoords0[2], glm::vec2(65535.0f, 1.0f));
    }
    {
        SCOPED_TRACE("NORMAL normalized BYTE (padded to 4-byte stride)");
        GltfBuilder builder;
        const std::vector<std::int8_t> normals = {0, 0, 127, 0, 0, 0, -128, 0, 127, 0, 0, 0};
        const int view = builder.addBufferView(normals.data(), normals.size(), 4);
        const int accessor = builder.addAccessor(view, gi::test::kGltfByte, 3, "VEC3", 0, true);
        placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{"NORMAL", accessor}}));
        const Loaded l = loadBuilt(builder);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_EQ(l.scene.primitives[0].normals[0], glm::vec3(0, 0, 1));
        EXPECT_EQ(l.scene.primitives[0].normals[1], glm::vec3(0, 0, -1));
        EXPECT_EQ(l.scene.primitives[0].normals[2], glm::vec3(1, 0, 0));
    }
    {
        SCOPED_TRACE("POSITION as non-normalized SHORT (KHR_mesh_quantization style)");
        GltfBuilder builder;
        const std::vector<std::int16_t> positions = {0, 0, 0, 0, -4, 0, 0, 0, 0, 4, 0, 0};
        const int view = builder.addBufferView(positions.data(), positions.size() * 2, 8);
        const int accessor = builder.addAccessor(view, gi::test::kGltfShort, 3, "VEC3");
        const json attributes = {{"POSITION", accessor}};
        placeMesh(builder, builder.addMesh(json::array({{{"attributes", attributes}}})));
        const Loaded l = loadBuilt(builder);
        ASSERT_TRUE(l.ok) << l.error;
        EXPECT_EQ(l.scene.primitives[0].positions[1], glm::vec3(-4, 0, 0));
        EXPECT_EQ(l.scene.primitives[0].positions[2], glm::vec3(0, 4, 0));
    }
}

TEST(GltfLoader, ReadsInterleavedAttributesThroughByteStride) {
    // One 24-byte vertex: POSITION float3 @0, NORMAL byte3 normalized @12 (+1 pad),
    // TEXCOORD_0 ushort2 normalized @16, COLOR_0 ubyte4 normalized @20.
    struct Vertex {
        float position[3];
        std::int8_t normal[4];
        std::uint16_t uv[2];
        std::uint8_t color[4];
    };
    static_assert(sizeof(Vertex) == 24);
    const std::vector<Vertex> vertices = {
            {{0, 0, 0}, {0, 0, 127, 0}, {0, 0}, {255, 0, 0, 255}},
            {{1, 0, 0}, {0, 0, 127, 0}, {65535, 0}, {0, 255, 0, 255}},
            {{0, 1, 0}, {0, 0, 127, 0}, {0, 65535}, {0, 0, 255, 51}},
    };
    GltfBuilder builder;
    const int view = builder.addBufferView(vertices, sizeof(Vertex));
    const int position = builder.addAccessor(view, gi::test::kGltfFloat, 3, "VEC3", 0);
    builder.doc()["accessors"][std::size_t(position)]["min"] = {0, 0, 0};
    builder.doc()["accessors"][std::size_t(position)]["max"] = {1, 1, 0};
    const int normal = builder.addAccessor(view, gi::test::kGltfByte, 3, "VEC3", 12, true);
    const int uv = builder.addAccessor(view, gi::test::kGltfUnsignedShort, 3, "VEC2", 16, true);
    const int color = builder.addAccessor(view, gi::test::kGltfUnsignedByte, 3, "VEC4", 20, true);
    const json attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv},
            {"COLOR_0", color}};
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", attributes}}})));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Primitive& p = loaded.scene.primitives[0];
    EXPECT_EQ(p.positions, kTriangle);
    EXPECT_EQ(p.normals[1], glm::vec3(0, 0, 1));
    EXPECT_EQ(p.texcoords0[1], glm::vec2(1, 0));
    EXPECT_EQ(p.texcoords0[2], glm::vec2(0, 1));
    EXPECT_EQ(p.colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(p.colors[2].w, 0.2f, kEps);
}

TEST(GltfLoader, AppliesSparseAccessors) {
    GltfBuilder builder;
    // Base positions with element 1 replaced sparsely.
    const int base = builder.addVec3({{0, 0, 0}, {9, 9, 9}, {0, 1, 0}}, false);
    const int sparseIndices = builder.addBufferView(std::vector<std::uint16_t>{1, 0});
    const int sparseValues = builder.addBufferView(std::vector<glm::vec3>{{1, 0, 0}});
    builder.doc()["accessors"][std::size_t(base)]["sparse"] = {{"count", 1},
            {"indices", {{"bufferView", sparseIndices}, {"componentType", 5123}}},
            {"values", {{"bufferView", sparseValues}}}};
    // TEXCOORD_0 without a bufferView: zeros, then element 2 set.
    const int uvValues = builder.addBufferView(std::vector<glm::vec2>{{0.25f, 0.75f}});
    const int uvIndices = builder.addBufferView(std::vector<std::uint8_t>{2, 0, 0, 0});
    const int uv = builder.addAccessor(-1, gi::test::kGltfFloat, 3, "VEC2");
    builder.doc()["accessors"][std::size_t(uv)]["sparse"] = {{"count", 1},
            {"indices", {{"bufferView", uvIndices}, {"componentType", 5121}}},
            {"values", {{"bufferView", uvValues}}}};
    placeMesh(builder, builder.addMesh(json::array(
                               {{{"attributes", {{"POSITION", base}, {"TEXCOORD_0", uv}}}}})));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].positions, kTriangle);
    EXPECT_EQ(loaded.scene.primitives[0].texcoords0,
            (std::vector<glm::vec2>{{0, 0}, {0, 0}, {0.25f, 0.75f}}));
}

// ---------------------------------------------------------------------------------------------
// Attributes

TEST(GltfLoader, NormalizesNormalsFromTheFile) {
    GltfBuilder builder;
    const int normals = builder.addVec3({{0, 0, 2}, {0, 3, 0}, {4, 0, 0}}, false);
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{"NORMAL", normals}}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].normals,
            (std::vector<glm::vec3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}));
}

TEST(GltfLoader, GeneratesAreaWeightedNormalsWhenMissing) {
    // Two triangles share vertex 0: a small one facing +Z and a large one facing +X.
    const std::vector<glm::vec3> positions = {
            {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 3, 0}, {0, 0, 3}};
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh(positions, {0, 1, 2, 0, 3, 4}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const std::vector<glm::vec3>& n = loaded.scene.primitives[0].normals;
    ASSERT_EQ(n.size(), positions.size());
    const glm::vec3 small = glm::cross(positions[1] - positions[0], positions[2] - positions[0]);
    const glm::vec3 large = glm::cross(positions[3] - positions[0], positions[4] - positions[0]);
    EXPECT_VEC3_NEAR(n[0], glm::normalize(small + large), kEps);
    EXPECT_VEC3_NEAR(n[1], glm::vec3(0, 0, 1), kEps);
    EXPECT_VEC3_NEAR(n[3], glm::vec3(1, 0, 0), kEps);
}

TEST(GltfLoader, ReadsTexcoordSetsZeroAndOne) {
    GltfBuilder builder;
    const int uv0 = builder.addVec2({{0, 0}, {1, 0}, {0, 1}});
    const int uv1 = builder.addVec2({{0.5f, 0.5f}, {0.25f, 0}, {0, 0.25f}});
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2},
                               {{"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].texcoords0[1], glm::vec2(1, 0));
    EXPECT_EQ(loaded.scene.primitives[0].texcoords1[0], glm::vec2(0.5f, 0.5f));
}

TEST(GltfLoader, ReadsColorVec3AndVec4AsLinearRgba) {
    GltfBuilder builder;
    const int rgb = builder.addVec3({{1, 0, 0}, {0, 1, 0}, {0, 0, 0.5f}}, false);
    const int rgba = builder.addVec4({{1, 0, 0, 0.5f}, {0, 1, 0, 1}, {0, 0, 1, 0}});
    const int positions = builder.addVec3(kTriangle);
    placeMesh(builder, builder.addMesh(json::array({
                               {{"attributes", {{"POSITION", positions}, {"COLOR_0", rgb}}}},
                               {{"attributes", {{"POSITION", positions}, {"COLOR_0", rgba}}}},
                       })));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    EXPECT_EQ(loaded.scene.primitives[0].colors[2], glm::vec4(0, 0, 0.5f, 1));
    EXPECT_EQ(loaded.scene.primitives[1].colors[0], glm::vec4(1, 0, 0, 0.5f));
}

// ---------------------------------------------------------------------------------------------
// Materials and textures

TEST(GltfLoader, ReadsMaterialFactorsAlphaAndEmissiveStrength) {
    GltfBuilder builder;
    builder.append("materials",
            {{"name", "masked"},
                    {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}}}},
                    {"emissiveFactor", {1.0, 0.5, 0.0}}, {"alphaMode", "MASK"},
                    {"alphaCutoff", 0.3}, {"doubleSided", true},
                    {"extensions", {{"KHR_materials_emissive_strength",
                                           {{"emissiveStrength", 4.0}}}}}});
    builder.append("materials", {{"alphaMode", "BLEND"}});
    builder.append("materials", json::object());
    builder.doc()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {}, 0));
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.materials.size(), 3u);
    const Material& m = loaded.scene.materials[0];
    EXPECT_EQ(m.name, "masked");
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_EQ(m.emissiveFactor, glm::vec3(4.0f, 2.0f, 0.0f));
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_NEAR(m.alphaCutoff, 0.3f, kEps);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(loaded.scene.materials[1].alphaMode, AlphaMode::Blend);
    const Material& d = loaded.scene.materials[2];
    EXPECT_EQ(d.baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(d.alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(d.alphaCutoff, 0.5f);
    EXPECT_FALSE(d.doubleSided);
    EXPECT_EQ(loaded.scene.primitives[0].material, 0);
    EXPECT_TRUE(loaded.warnings.empty()) << allWarnings(loaded);
}

// A 2x2 image of `channels` channels: pixel i has every channel = 60 * (i + 1) + channel.
std::vector<std::uint8_t> testPixels(int channels) {
    std::vector<std::uint8_t> pixels;
    for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < channels; ++c) pixels.push_back(std::uint8_t(60 * (i + 1) + c));
    }
    return pixels;
}

// One material per image, each a base-colour texture of a triangle mesh; images embedded as
// data URIs.
GltfBuilder texturedScene(const std::vector<std::vector<std::uint8_t>>& images,
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

TEST(GltfLoader, DecodesOneToFourChannelImagesToRgba8) {
    std::vector<std::vector<std::uint8_t>> images;
    for (int channels = 1; channels <= 4; ++channels) {
        images.push_back(gi::test::encodePng(2, 2, channels, testPixels(channels)));
    }
    const Loaded loaded = loadBuilt(texturedScene(images));
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.textures.size(), 4u);
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(std::to_string(channels) + " channels");
        const Texture& t = loaded.scene.textures[std::size_t(channels - 1)];
        ASSERT_EQ(t.width, 2);
        ASSERT_EQ(t.height, 2);
        ASSERT_EQ(t.rgba8.size(), 16u);
        EXPECT_TRUE(t.srgb);
        for (int i = 0; i < 4; ++i) {
            const std::uint8_t v = std::uint8_t(60 * (i + 1));
            const std::uint8_t* px = &t.rgba8[std::size_t(i) * 4];
            // Grey expands to (v, v, v); grey+alpha keeps its alpha; no alpha means 255.
            const std::uint8_t r = v, g = channels >= 3 ? v + 1 : v, b = channels >= 3 ? v + 2 : v;
            const std::uint8_t a = channels == 2 ? v + 1 : channels == 4 ? v + 3 : 255;
            EXPECT_EQ(px[0], r);
            EXPECT_EQ(px[1], g);
            EXPECT_EQ(px[2], b);
            EXPECT_EQ(px[3], a);
        }
        EXPECT_EQ(loaded.scene.materials[std::size_t(channels - 1)].baseColorTexture,
                channels - 1);
    }
}

TEST(GltfLoader, DecodesJpegImages) {
    std::vector<std::uint8_t> orange;
    for (int i = 0; i < 64; ++i) orange.insert(orange.end(), {200, 100, 50});
    const Loaded loaded =
            loadBuilt(texturedScene({gi::test::encodeJpeg(8, 8, 3, orange)}, "image/jpeg"));
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Texture& t = loaded.scene.textures[0];
    ASSERT_EQ(t.width, 8);
    ASSERT_EQ(t.rgba8.size(), 8u * 8u * 4u);
    // JPEG is lossy: a flat colour at quality 95 decodes within a few steps.
    EXPECT_NEAR(t.rgba8[0], 200, 4);
    EXPECT_NEAR(t.rgba8[1], 100, 4);
    EXPECT_NEAR(t.rgba8[2], 50, 4);
    EXPECT_EQ(t.rgba8[3], 255);
}

TEST(GltfLoader, RecordsSamplerWrapAndTexCoordSets) {
    GltfBuilder builder = texturedScene({gi::test::encodePng(2, 2, 3, testPixels(3)),
            gi::test::encodePng(2, 2, 3, testPixels(3))});
    builder.append("samplers", {{"wrapS", 33071}, {"wrapT", 33648}});
    builder.doc()["textures"][1]["sampler"] = 0;
    builder.doc()["materials"][1]["emissiveTexture"] = {{"index", 0}, {"texCoord", 1}};
    builder.doc()["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    builder.doc()["meshes"][0]["primitives"][1]["attributes"]["TEXCOORD_1"] =
            builder.addVec2({{0, 0}, {1, 0}, {0, 1}});
    const Loaded loaded = loadBuilt(builder);
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.textures.size(), 2u);
    EXPECT_EQ(loaded.scene.textures[0].wrapS, 10497); // no sampler: REPEAT
    EXPECT_EQ(loaded.scene.textures[1].wrapS, 33071);
    EXPECT_EQ(loaded.scene.textures[1].wrapT, 33648);
    const Material& m = loaded.scene.materials[1];
    EXPECT_EQ(m.baseColorTexture, 1);
    EXPECT_EQ(m.baseColorTexCoord, 1);
    EXPECT_EQ(m.emissiveTexture, 0) << "glTF texture 0 is shared, not decoded twice";
    EXPECT_EQ(m.emissiveTexCoord, 1);
}

TEST(GltfLoader, LoadsExternalImageFilesWithPercentEncodedUris) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::vector<std::uint8_t> png = gi::test::encodePng(2, 2, 4, testPixels(4));
    gi::test::writeBytes(dir / "base colour.png", png.data(), png.size());
    GltfBuilder builder = texturedScene({});
    builder.append("images", {{"uri", "base%20colour.png"}});
    builder.append("textures", {{"source", 0}});
    builder.append("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    builder.doc()["meshes"][0]["primitives"] = json::array(
            {{{"attributes", {{"POSITION", builder.addVec3(kTriangle)}}}, {"material", 0}}});
    const Loaded loaded = loadFile(builder.writeGltf(dir, "scene"));
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.textures.size(), 1u);
    EXPECT_EQ(loaded.scene.textures[0].rgba8[3], 63);
    EXPECT_EQ(loaded.scene.textures[0].name, "base%20colour.png");
    // The primitive has no TEXCOORD_0 but its material samples through it.
    EXPECT_EQ(loaded.scene.primitives[0].texcoords0.size(), 3u);
    EXPECT_TRUE(hasWarning(loaded, "TEXCOORD_0, which the primitive lacks")) << allWarnings(loaded);
}

TEST(GltfLoader, LoadsImagesFromGlbBufferViews) {
    GltfBuilder builder = texturedScene({});
    const std::vector<std::uint8_t> png = gi::test::encodePng(2, 2, 3, testPixels(3));
    const int view = builder.addBufferView(png);
    builder.append("images", {{"bufferView", view}, {"mimeType", "image/png"}});
    builder.append("textures", {{"source", 0}});
    builder.append("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    builder.doc()["meshes"][0]["primitives"] = json::array(
            {{{"attributes", {{"POSITION", builder.addVec3(kTriangle)},
                                     {"TEXCOORD_0", builder.addVec2({{0, 0}, {1, 0}, {0, 1}})}}},
                    {"material", 0}}});
    const auto dir = gi::test::freshGltfTestDir(testName());
    const Loaded loaded = loadFile(builder.writeGlb(dir, "scene"));
    ASSERT_TRUE(loaded.ok) << loaded.error;
    ASSERT_EQ(loaded.scene.textures.size(), 1u);
    EXPECT_EQ(loaded.scene.textures[0].rgba8[0], 60);
    EXPECT_EQ(loaded.scene.textures[0].rgba8[3], 255);
}

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
// Rejected input: every message is "<file>: <element>: <what>"

TEST(GltfLoaderError, UnreadableFile) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = (dir / "missing.gltf").string();
    expectError(loadFile(path), path, "file", "cannot read (No such file or directory)");
    expectError(loadFile(dir.string()), dir.string(), "file", "not a regular file");
}

TEST(GltfLoaderError, MalformedJson) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    gi::test::writeText(dir / "broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    const std::string path = (dir / "broken.gltf").string();
    expectError(loadFile(path), path, "glTF", "parse error");
}

TEST(GltfLoaderError, LeavesTheOutputSceneUntouched) {
    Scene scene;
    scene.sourcePath = "before";
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_FALSE(loadGltf("/nonexistent/x.gltf", scene, error, warnings));
    EXPECT_EQ(scene.sourcePath, "before");
}

TEST(GltfLoaderError, MissingExternalBuffer) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = triangleScene().writeGltf(dir, "scene");
    std::filesystem::remove(dir / "scene.bin");
    expectError(loadFile(path), path, "buffers[0]",
            "cannot read 'scene.bin' (No such file or directory)");
}

TEST(GltfLoaderError, ExternalBufferOfTheWrongSize) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = triangleScene().writeGltf(dir, "scene");
    gi::test::writeText(dir / "scene.bin", "short");
    expectError(loadFile(path), path, "buffers[0]", "'scene.bin' holds 5 bytes but byteLength is");
}

TEST(GltfLoaderError, MissingImageFile) {
    GltfBuilder builder = texturedScene({});
    builder.append("images", {{"uri", "missing.png"}});
    builder.append("textures", {{"source", 0}});
    builder.append("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    builder.doc()["meshes"][0]["primitives"] = json::array(
            {{{"attributes", {{"POSITION", builder.addVec3(kTriangle)}}}, {"material", 0}}});
    expectBuiltError(builder, "images[0]", "cannot read 'missing.png' (No such file or directory)");
}

TEST(GltfLoaderError, CorruptImageFile) {
    const auto dir = gi::test::freshGltfTestDir(testName());
    gi::test::writeText(dir / "bad.png", "this is not a PNG file at all");
    GltfBuilder builder = texturedScene({});
    builder.append("images", {{"uri", "bad.png"}});
    builder.append("textures", {{"source", 0}});
    builder.append("materials", {{"emissiveTexture", {{"index", 0}}}});
    builder.doc()["meshes"][0]["primitives"] = json::array(
            {{{"attributes", {{"POSITION", builder.addVec3(kTriangle)}}}, {"material", 0}}});
    const std::string path = builder.writeGltf(dir, "scene");
    expectError(loadFile(path), path, "images[0]", "'bad.png': not a PNG or JPEG image");
}

TEST(GltfLoaderError, CorruptEmbeddedImage) {
    const std::vector<std::uint8_t> png = gi::test::encodePng(2, 2, 3, testPixels(3));
    const std::vector<std::uint8_t> truncated(png.begin(), png.begin() + 40);
    expectBuiltError(texturedScene({truncated}), "images[0]", "");
}

TEST(GltfLoaderError, AccessorOutsideItsBufferView) {
    GltfBuilder builder = triangleScene();
    builder.doc()["accessors"][0]["count"] = 4; // 4 x 12 bytes in a 36-byte view
    expectBuiltError(builder, "accessors[0]",
            "byteOffset + (count-1)*stride + elementSize (48) exceeds bufferViews[0].byteLength "
            "(36)");
}

TEST(GltfLoaderError, AccessorByteOffsetOutsideItsBufferView) {
    GltfBuilder builder = triangleScene();
    builder.doc()["accessors"][0]["byteOffset"] = 4;
    expectBuiltError(builder, "accessors[0]", "(40) exceeds bufferViews[0].byteLength (36)");
}

TEST(GltfLoaderError, BufferViewOutsideItsBuffer) {
    GltfBuilder builder = triangleScene();
    builder.doc()["bufferViews"][1]["byteOffset"] = 1000;
    expectBuiltError(builder, "bufferViews[1]", "byteOffset + byteLength (1006) exceeds "
                                                "buffers[0].byteLength (42)");
}

TEST(GltfLoaderError, HugeCountsFailBeforeAllocating) {
    GltfBuilder builder = triangleScene();
    builder.doc()["accessors"][0]["count"] = std::uint64_t(1) << 62; // count*12 overflows
    expectBuiltError(builder, "accessors[0]", "(more than 2^64) exceeds bufferViews[0]");
    builder.doc()["accessors"][0]["count"] = std::uint64_t(1) << 40;
    expectBuiltError(builder, "accessors[0]", "exceeds bufferViews[0].byteLength (36)");
}

TEST(GltfLoaderError, SparseAccessorCountOverTheLimit) {
    GltfBuilder builder;
    const int values = builder.addBufferView(std::vector<glm::vec3>{{1, 0, 0}});
    const int indices = builder.addBufferView(std::vector<std::uint32_t>{1});
    const int positions = builder.addAccessor(-1, gi::test::kGltfFloat, 1ull << 40, "VEC3");
    builder.doc()["accessors"][std::size_t(positions)]["sparse"] = {{"count", 1},
            {"indices", {{"bufferView", indices}, {"componentType", 5125}}},
            {"values", {{"bufferView", values}}}};
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"POSITION", positions}}}}})));
    expectBuiltError(builder, "accessors[0]", "exceeds the loader's limit");
}

TEST(GltfLoaderError, SparseIndexOutOfRange) {
    GltfBuilder builder;
    const int base = builder.addVec3(kTriangle, false);
    const int indices = builder.addBufferView(std::vector<std::uint16_t>{3, 0});
    const int values = builder.addBufferView(std::vector<glm::vec3>{{1, 0, 0}});
    builder.doc()["accessors"][std::size_t(base)]["sparse"] = {{"count", 1},
            {"indices", {{"bufferView", indices}, {"componentType", 5123}}},
            {"values", {{"bufferView", values}}}};
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"POSITION", base}}}}})));
    expectBuiltError(builder, "accessors[0]", "sparse index 3 (entry 0) is out of range (count 3)");
}

TEST(GltfLoaderError, IndexOutOfRange) {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 7}));
    expectBuiltError(builder, "accessors[1]",
            "index 7 at element 2 is out of range (POSITION of meshes[0].primitives[0] has 3 "
            "vertices)");
}

TEST(GltfLoaderError, NonFinitePosition) {
    GltfBuilder builder;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int positions = builder.addVec3({{0, 0, 0}, {nan, 0, 0}, {0, 1, 0}}, false);
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"POSITION", positions}}}}})));
    expectBuiltError(builder, "accessors[0]",
            "element 1 (nan, 0, 0) is not finite (POSITION of meshes[0].primitives[0])");
}

TEST(GltfLoaderError, NonFiniteNormal) {
    GltfBuilder builder;
    const float inf = std::numeric_limits<float>::infinity();
    const int normals = builder.addVec3({{0, 0, 1}, {0, 0, 1}, {0, inf, 1}}, false);
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{"NORMAL", normals}}));
    expectBuiltError(builder, "accessors[0]", "element 2 (0, inf, 1) is not finite (NORMAL");
}

TEST(GltfLoaderError, NonFiniteTexcoord) {
    GltfBuilder builder;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int uv = builder.addVec2({{0, 0}, {nan, 0}, {0, 1}});
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{"TEXCOORD_0", uv}}));
    expectBuiltError(builder, "accessors[0]", "is not finite (TEXCOORD_0");
}

TEST(GltfLoaderError, NonFiniteNodeTransforms) {
    // JSON cannot spell NaN or infinity; 1e300 is finite as a double but not as a float.
    GltfBuilder builder = triangleScene();
    builder.doc()["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expectBuiltError(builder, "nodes[0]", "matrix must be 16 finite numbers");
    builder.doc()["nodes"][0].erase("matrix");
    builder.doc()["nodes"][0]["scale"] = {1, -1e300, 1};
    expectBuiltError(builder, "nodes[0]", "scale must be 3 finite numbers");
    builder.doc()["nodes"][0]["scale"] = {1, 1};
    expectBuiltError(builder, "nodes[0]", "scale must be 3 finite numbers");
    builder.doc()["nodes"][0].erase("scale");
    builder.doc()["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectBuiltError(builder, "nodes[0]", "rotation is not a unit quaternion");
}

TEST(GltfLoaderError, WorldTransformOverflow) {
    GltfBuilder builder;
    const int mesh = builder.addTriangleMesh(kTriangle, {0, 1, 2});
    const int child = builder.addNode({{"mesh", mesh}, {"scale", {1e30, 1e30, 1e30}}});
    builder.addScene({builder.addNode({{"children", {child}}, {"scale", {1e30, 1e30, 1e30}}})});
    expectBuiltError(builder, "nodes[0]", "world transform is not finite");
}

TEST(GltfLoaderError, CoordinatesTooFarForSinglePrecision) {
    GltfBuilder builder;
    placeMesh(builder, builder.addTriangleMesh({{0, 0, 0}, {2e31f, 0, 0}, {0, 1, 0}}, {0, 1, 2}));
    expectBuiltError(builder, "nodes[0]", "places vertices beyond +-1e18 m");
}

TEST(GltfLoaderError, CyclicNodeGraph) {
    GltfBuilder builder;
    builder.addNode({{"children", {1}}});
    builder.addNode({{"children", {2}}});
    builder.addNode({{"children", {0}}});
    builder.addScene({});
    expectBuiltError(builder, "nodes[0]",
            "is part of a cycle in the node hierarchy (nodes[0] -> nodes[1] -> nodes[2] -> "
            "nodes[0])");
    GltfBuilder self;
    self.addNode({{"children", {0}}});
    expectBuiltError(self, "nodes[0]",
            "is part of a cycle in the node hierarchy (nodes[0] -> nodes[0])");
}

TEST(GltfLoaderError, NodeWithTwoParents) {
    GltfBuilder builder;
    builder.addNode({{"children", {2}}});
    builder.addNode({{"children", {2}}});
    builder.addNode(json::object());
    builder.addScene({0, 1});
    expectBuiltError(builder, "nodes[2]", "has two parents (nodes[0] and nodes[1])");
}

TEST(GltfLoaderError, SceneRootThatIsAChild) {
    GltfBuilder builder;
    builder.addNode({{"children", {1}}});
    builder.addNode(json::object());
    builder.addScene({0, 1});
    expectBuiltError(builder, "scenes[0]",
            "nodes[1] is listed as a root but is a child of nodes[0]");
}

TEST(GltfLoaderError, UnsupportedRequiredExtension) {
    GltfBuilder builder = triangleScene();
    builder.doc()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    builder.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectBuiltError(builder, "extensionsRequired",
            "extension 'KHR_draco_mesh_compression' is not supported");
}

TEST(GltfLoaderError, PrimitiveWithoutPosition) {
    GltfBuilder builder;
    const int normals = builder.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, false);
    placeMesh(builder, builder.addMesh(json::array({{{"attributes", {{"NORMAL", normals}}}}})));
    expectBuiltError(builder, "meshes[0].primitives[0]", "has no POSITION attribute");
}

TEST(GltfLoaderError, AttributeOfTheWrongTypeOrCount) {
    GltfBuilder builder;
    const int uv = builder.addVec2({{0, 0}, {1, 0}, {0, 1}});
    placeMesh(builder, builder.addTriangleMesh(kTriangle, {0, 1, 2}, {{"NORMAL", uv}}));
    expectBuiltError(builder, "meshes[0].primitives[0]", "NORMAL (accessors[0]) has type VEC2");

    GltfBuilder counts;
    const int shortUv = counts.addVec2({{0, 0}, {1, 0}});
    placeMesh(counts, counts.addTriangleMesh(kTriangle, {0, 1, 2}, {{"TEXCOORD_0", shortUv}}));
    expectBuiltError(counts, "meshes[0].primitives[0]",
            "TEXCOORD_0 has 2 elements but POSITION has 3");
}

TEST(GltfLoaderError, IndicesOfANonIndexType) {
    GltfBuilder builder;
    const int positions = builder.addVec3(kTriangle);
    const int indices = builder.addAccessor(builder.addBufferView(std::vector<float>{0, 1, 2}),
            gi::test::kGltfFloat, 3, "SCALAR");
    const json primitive = {{"attributes", {{"POSITION", positions}}}, {"indices", indices}};
    placeMesh(builder, builder.addMesh(json::array({primitive})));
    expectBuiltError(builder, "accessors[1]", "indices must be SCALAR");
}

TEST(GltfLoaderError, InvalidPrimitiveMode) {
    GltfBuilder builder = triangleScene();
    builder.doc()["meshes"][0]["primitives"][0]["mode"] = 9;
    expectBuiltError(builder, "meshes[0].primitives[0]", "mode 9 is not a glTF primitive mode");
}

TEST(GltfLoaderError, InvalidReferences) {
    {
        SCOPED_TRACE("material");
        GltfBuilder builder = triangleScene();
        builder.doc()["meshes"][0]["primitives"][0]["material"] = 5;
        expectBuiltError(builder, "meshes[0].primitives[0]",
                "material 5 does not exist (the file has 0 materials)");
    }
    {
        SCOPED_TRACE("texture");
        GltfBuilder builder = triangleScene();
        builder.append("materials",
                {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}});
        expectBuiltError(builder, "materials[0]",
                "pbrMetallicRoughness.baseColorTexture.index 3 does not exist (the file has 0 "
                "textures)");
    }
    {
        SCOPED_TRACE("image");
        GltfBuilder builder = triangleScene();
        builder.append("textures", {{"source", 4}});
        expectBuiltError(builder, "textures[0]", "source 4 does not exist (the file has 0 images)");
    }
    {
        SCOPED_TRACE("sampler");
        GltfBuilder builder = texturedScene({gi::test::encodePng(2, 2, 3, testPixels(3))});
        builder.doc()["textures"][0]["sampler"] = 2;
        expectBuiltError(builder, "textures[0]", "sampler 2 does not exist (the file has 0 "
                                                 "samplers)");
    }
    {
        SCOPED_TRACE("sampler wrap mode");
        GltfBuilder builder = triangleScene();
        builder.append("samplers", {{"wrapS", 1234}});
        expectBuiltError(builder, "samplers[0]", "wrapS 1234 is not CLAMP_TO_EDGE");
    }
    {
        SCOPED_TRACE("attribute accessor");
        GltfBuilder builder = triangleScene();
        builder.doc()["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42;
        expectBuiltError(builder, "meshes[0].primitives[0]",
                "attribute NORMAL 42 does not exist (the file has 2 accessors)");
    }
    {
        SCOPED_TRACE("node mesh");
        GltfBuilder builder = triangleScene();
        builder.doc()["nodes"][0]["mesh"] = 3;
        expectBuiltError(builder, "nodes[0]", "mesh 3 does not exist (the file has 1 meshes)");
    }
    {
        SCOPED_TRACE("node child");
        GltfBuilder builder = triangleScene();
        builder.doc()["nodes"][0]["children"] = {7};
        expectBuiltError(builder, "nodes[0]", "child 7 does not exist (the file has 1 nodes)");
    }
    {
        SCOPED_TRACE("scene");
        GltfBuilder builder = triangleScene();
        builder.doc()["scene"] = 3;
        expectBuiltError(builder, "scene", "scene 3 does not exist (the file has 1 scenes)");
    }
    {
        SCOPED_TRACE("light");
        GltfBuilder builder = triangleScene();
        builder.doc()["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
        expectBuiltError(builder, "nodes[0]",
                "KHR_lights_punctual.light 0 does not exist (the file has 0 lights)");
    }
}

TEST(GltfLoaderError, InvalidLightAndCameraParameters) {
    {
        SCOPED_TRACE("spot cone");
        GltfBuilder builder = triangleScene();
        builder.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "spot"},
                {"spot", {{"innerConeAngle", 0.8}, {"outerConeAngle", 0.4}}}}};
        expectBuiltError(builder, "KHR_lights_punctual.lights[0]",
                "must satisfy 0 <= inner < outer <= pi/2");
    }
    {
        SCOPED_TRACE("light type");
        GltfBuilder builder = triangleScene();
        builder.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "area"}}};
        expectBuiltError(builder, "KHR_lights_punctual.lights[0]",
                "type 'area' is not point, spot or directional");
    }
    {
        SCOPED_TRACE("negative intensity");
        GltfBuilder builder = triangleScene();
        builder.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {
                {{"type", "point"}, {"intensity", -1.0}}};
        expectBuiltError(builder, "KHR_lights_punctual.lights[0]", "intensity");
    }
    {
        SCOPED_TRACE("camera yfov");
        GltfBuilder builder = triangleScene();
        builder.append("cameras", {{"type", "perspective"},
                                          {"perspective", {{"yfov", -1.0}, {"znear", 0.1}}}});
        expectBuiltError(builder, "cameras[0]", "perspective.yfov");
    }
    {
        SCOPED_TRACE("material alphaMode");
        GltfBuilder builder = triangleScene();
        builder.append("materials", {{"alphaMode", "CUTOUT"}});
        expectBuiltError(builder, "materials[0]",
                "alphaMode 'CUTOUT' is not OPAQUE, MASK or BLEND");
    }
}

TEST(GltfLoaderError, MessagesStayOnOneLineWhateverTheFileSays) {
    GltfBuilder builder = triangleScene();
    builder.append("materials", {{"alphaMode", "LINE\nBREAK"}});
    expectBuiltError(builder, "materials[0]", "alphaMode 'LINE BREAK' is not");
}

TEST(GltfLoaderError, GlbChunkLongerThanTheFile) {
    std::vector<std::uint8_t> glb = triangleScene().glb();
    const std::size_t jsonLength = glb[12] | glb[13] << 8;
    const std::size_t binHeader = 20 + jsonLength;
    glb[binHeader] = std::uint8_t(glb[binHeader] + 8); // BIN chunk claims 8 more bytes
    const auto dir = gi::test::freshGltfTestDir(testName());
    gi::test::writeBytes(dir / "scene.glb", glb.data(), glb.size());
    const std::string path = (dir / "scene.glb").string();
    expectError(loadFile(path), path, "GLB header", "BIN chunk length");
}

TEST(GltfLoaderError, GlbImageBufferViewOutsideItsBuffer) {
    GltfBuilder builder = texturedScene({});
    const std::vector<std::uint8_t> png = gi::test::encodePng(2, 2, 3, testPixels(3));
    const int view = builder.addBufferView(png);
    builder.doc()["bufferViews"][std::size_t(view)]["byteLength"] = 100000;
    builder.append("images", {{"bufferView", view}, {"mimeType", "image/png"}});
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = builder.writeGlb(dir, "scene");
    expectError(loadFile(path), path, "images[0]", "bufferViews[2] does not lie inside its buffer");
}

TEST(GltfLoaderError, DeeplyNestedJson) {
    GltfBuilder builder = triangleScene();
    json extras = json::array();
    for (int i = 0; i < 1000; ++i) extras = json::array({extras});
    builder.doc()["extras"] = extras;
    expectBuiltError(builder, "JSON", "nesting deeper than 128 levels");
}

TEST(GltfLoaderError, SceneLargerThanTheLimits) {
    GltfLimits limits;
    limits.maxVertices = 2;
    const auto dir = gi::test::freshGltfTestDir(testName());
    const std::string path = triangleScene().writeGltf(dir, "scene");
    expectError(loadFile(path, limits), path, "meshes[0].primitives[0]",
            "exceeds the loader's limit of 2 vertices");

    GltfLimits imageLimits;
    imageLimits.maxTotalImagePixels = 7; // two 2x2 images need 8
    const std::string textured =
            texturedScene({gi::test::encodePng(2, 2, 3, testPixels(3)),
                                  gi::test::encodePng(2, 2, 1, testPixels(1))})
                    .writeGltf(dir, "textured");
    expectError(loadFile(textured, imageLimits), textured, "images[1]",
            "exceed the loader's limit of 7 pixels in total");
}

// ---------------------------------------------------------------------------------------------
// The real Sponza, when present (DESIGN.md: read from ../shared/assets, never committed).

TEST(GltfLoaderSponza, LoadsWithAllTrianglesAndTextures) {
    const std::filesystem::path path = std::filesystem::path(VOXATLAS_TEST_DATA_DIR) /
                                       "../../shared/assets/sponza/Sponza.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "Sponza not found at " << path;
    const auto start = std::chrono::steady_clock::now();
    const Loaded loaded = loadFile(path.string());
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
