// glTF loader tests of materials and textures: factors, alpha modes, emissive strength, image
// decoding of every channel count and format, samplers, and image sources.
#include "GltfLoaderTestSupport.h"

#include <gtest/gtest.h>

namespace gi::scene {
namespace {

using namespace loadertest;

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

} // namespace
} // namespace gi::scene
