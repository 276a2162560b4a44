// glTF loader tests of accessors (every component type, interleaving, sparse data) and of the
// vertex attributes read through them (normals, texture coordinates, colours).
#include "GltfLoaderTestSupport.h"

#include <gtest/gtest.h>

namespace gi::scene {
namespace {

using namespace loadertest;

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

} // namespace
} // namespace gi::scene
