// Any glTF a user opens looks right: files without lights or cameras (tests/first_light,
// written by make_first_light_scenes.py, and Sponza, which has no camera) rendered with the
// defaults chosen from their geometry (src/scene/SceneDefaults.h) show a lit picture, and
// `voxatlas info` says what was chosen and why.
#include "Process.h"
#include "Sponza.h"

#include "core/ImageIO.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace gi::test {
namespace {

const std::string kFirstLight = std::string(VOXATLAS_DATA_DIR) + "/tests/first_light/";

// A pixel counts as lit above this linear luminance (about 25/255 in the sRGB PNG): well
// above the black of an unlit or empty pixel, well below any surface auto exposure shows.
constexpr float kLitLuminance = 0.01f;

struct PictureStats {
    float meanLuminance = 0.0f;
    float litFraction = 0.0f;
};

PictureStats stats(const core::Image& image) {
    PictureStats s;
    const int pixels = image.width * image.height;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float luminance = glm::dot(image.at(x, y), glm::vec3(0.2126f, 0.7152f, 0.0722f));
            s.meanLuminance += luminance / float(pixels);
            s.litFraction += luminance > kLitLuminance ? 1.0f / float(pixels) : 0.0f;
        }
    }
    return s;
}

// The PNG of `voxatlas render scene --mode direct --exposure auto` at 64x64.
core::Image renderDefault(const std::string& scene, const std::string& name) {
    const std::string dir = makeTempDir("first_light_" + name);
    const std::string png = dir + "/" + name + ".png";
    const ProcessResult r = runVoxatlas({"render", scene, "--mode", "direct", "--exposure",
            "auto", "--width", "64", "--height", "64", "--out", png, "--hdr",
            dir + "/" + name + ".pfm"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    EXPECT_TRUE(core::readPng(png, image, error)) << error;
    return image;
}

class FirstLight : public ::testing::TestWithParam<const char*> {};

TEST_P(FirstLight, SceneWithoutLightsOrCamerasIsLit) {
    const core::Image image = renderDefault(kFirstLight + GetParam() + ".gltf", GetParam());
    ASSERT_FALSE(image.empty());
    const PictureStats s = stats(image);
    // Auto exposure scales the picture, so a lit scene lands in a middle range; a black or
    // nearly black one (an unlit side, a camera inside or outside the geometry) does not.
    EXPECT_GE(s.meanLuminance, 0.04f);
    EXPECT_LE(s.meanLuminance, 0.8f);
    EXPECT_GE(s.litFraction, 0.25f) << "the scene fills too little of the frame, or is dark";
}

INSTANTIATE_TEST_SUITE_P(Scenes, FirstLight,
        ::testing::Values("textured_box", "triangle_no_indices", "sparse_plane",
                "interleaved_box", "vertex_colour_board", "ground_with_block", "closed_room"),
        [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

TEST(FirstLightInfo, SaysWhatWasChosenAndWhy) {
    const ProcessResult room = runVoxatlas({"info", kFirstLight + "closed_room.gltf"});
    ASSERT_EQ(room.exitCode, 0) << room.err;
    EXPECT_NE(room.out.find("chosen: none in the file; interior (100% of survey rays hit front "
                            "faces) -> ceiling point light"),
            std::string::npos) << room.out;
    EXPECT_NE(room.out.find("chosen: none in the file; interior -> standing 1.5 m above the floor"),
            std::string::npos) << room.out;
    const ProcessResult box = runVoxatlas({"info", kFirstLight + "textured_box.gltf"});
    ASSERT_EQ(box.exitCode, 0) << box.err;
    EXPECT_NE(box.out.find("object or outdoor scene (0% of survey rays hit front faces, 100% "
                           "back faces, 0% escape) -> sun"),
            std::string::npos) << box.out;
}

// A box lit only by an emissive ceiling panel: the panel is its light (no invented one) and
// lights the room.
TEST(FirstLightEmissive, PanelIsTheOnlyLightAndLightsTheBox) {
    const std::string scene = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box_emissive.gltf";
    const ProcessResult info = runVoxatlas({"info", scene});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("lights     1\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("chosen: emissive surfaces: 2 emissive triangle(s)"), std::string::npos)
            << info.out;
    EXPECT_NE(info.out.find("[0] area"), std::string::npos) << info.out;
    EXPECT_EQ(info.out.find("(default) colour"), std::string::npos) << info.out;
    const core::Image image = renderDefault(scene, "cornell_box_emissive");
    ASSERT_FALSE(image.empty());
    const PictureStats s = stats(image);
    EXPECT_GE(s.meanLuminance, 0.04f);
    EXPECT_LE(s.meanLuminance, 0.8f);
    EXPECT_GE(s.litFraction, 0.25f);
}

TEST(FirstLightSponza, DefaultCameraStandsInsideAndSeesALitAtrium) {
    VOXATLAS_SPONZA_OR_SKIP(sponza);
    const ProcessResult info = runVoxatlas({"info", sponza});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("interior"), std::string::npos) << info.out;
    float min[3], max[3], eye[3];
    const std::size_t bounds = info.out.find("bounds     min");
    ASSERT_NE(bounds, std::string::npos);
    ASSERT_EQ(std::sscanf(info.out.c_str() + bounds, "bounds     min (%f, %f, %f) max (%f, %f, %f)",
                      &min[0], &min[1], &min[2], &max[0], &max[1], &max[2]), 6);
    const std::size_t camera = info.out.find("[0] (default) at (");
    ASSERT_NE(camera, std::string::npos) << info.out;
    ASSERT_EQ(std::sscanf(info.out.c_str() + camera, "[0] (default) at (%f, %f, %f)", &eye[0],
                      &eye[1], &eye[2]), 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_GT(eye[i], min[i]) << "axis " << i;
        EXPECT_LT(eye[i], max[i]) << "axis " << i;
    }
    const PictureStats s = stats(renderDefault(sponza, "sponza"));
    EXPECT_GE(s.litFraction, 0.6f);
    EXPECT_GE(s.meanLuminance, 0.04f);
}

} // namespace
} // namespace gi::test
