// glTF loader tests of rejected input: unreadable files and buffers, broken images, accessors
// outside their data, non-finite values. Every message is "<file>: <element>: <what>".
#include "GltfLoaderTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

namespace gi::scene {
namespace {

using namespace loadertest;

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

} // namespace
} // namespace gi::scene
