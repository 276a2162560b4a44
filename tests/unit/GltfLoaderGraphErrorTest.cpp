// glTF loader tests of rejected input, continued: node graphs, references, attribute types,
// light and camera parameters, GLB containers and the loader's size limits.
#include "GltfLoaderTestSupport.h"

#include <gtest/gtest.h>

namespace gi::scene {
namespace {

using namespace loadertest;

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

} // namespace
} // namespace gi::scene
