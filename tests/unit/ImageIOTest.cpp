#include "core/ImageIO.h"

#include "ImageCompare.h"
#include "Process.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace gi::core {
namespace {

Image gradient(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) image.set(x, y, {float(x) / float(w), float(y) / float(h), 3.5f});
    }
    return image;
}

TEST(ImageIO, HdrFormatsRoundTripExactly) {
    const std::string dir = test::makeTempDir("imageio-hdr");
    const Image image = gradient(7, 5);
    for (const char* name : {"/a.pfm", "/a.exr"}) {
        std::string error;
        ASSERT_TRUE(writeHdr(dir + name, image, error)) << error;
        Image back;
        ASSERT_TRUE(readHdr(dir + name, back, error)) << error;
        ASSERT_EQ(back.width, 7);
        ASSERT_EQ(back.height, 5);
        EXPECT_EQ(back.rgb, image.rgb) << name << ": 32-bit float storage must be lossless";
    }
    std::filesystem::remove_all(dir);
}

TEST(ImageIO, PngIsClampedSrgb) {
    const std::string dir = test::makeTempDir("imageio-png");
    Image image(2, 1);
    image.set(0, 0, {0.0f, 0.2140f, 1.0f});   // linear 0.214 encodes to sRGB 0.5
    image.set(1, 0, {-1.0f, 7.0f, 0.5f});     // out of range values clamp
    std::string error;
    ASSERT_TRUE(writePng(dir + "/a.png", image, error)) << error;
    Image back;
    ASSERT_TRUE(readPng(dir + "/a.png", back, error)) << error;
    EXPECT_NEAR(back.at(0, 0).g, 0.2140f, 0.003f);
    EXPECT_EQ(back.at(1, 0).r, 0.0f);
    EXPECT_EQ(back.at(1, 0).g, 1.0f);
    EXPECT_FALSE(std::filesystem::exists(dir + "/a.png.partial")) << "temporary file left behind";
    std::filesystem::remove_all(dir);
}

TEST(ImageIO, FailedWriteLeavesNothing) {
    const std::string dir = test::makeTempDir("imageio-fail");
    std::string error;
    EXPECT_FALSE(writePng(dir + "/missing/a.png", gradient(4, 4), error));
    EXPECT_NE(error.find("a.png"), std::string::npos) << error;
    EXPECT_FALSE(writeHdr(dir + "/a.hdr", gradient(4, 4), error));
    EXPECT_FALSE(std::filesystem::exists(dir + "/a.hdr"));
    EXPECT_FALSE(checkWritable(dir + "/missing/a.png", error));
    EXPECT_FALSE(checkWritable(dir, error)) << "a directory is not an output file";
    EXPECT_TRUE(checkWritable(dir + "/ok.png", error)) << error;
    EXPECT_FALSE(std::filesystem::exists(dir + "/ok.png")) << "checking must not create the file";
    std::filesystem::remove_all(dir);
}

TEST(ImageIO, BoxDownsampleAveragesPixelSquares) {
    Image image(4, 2);
    for (int x = 0; x < 4; ++x) {
        image.set(x, 0, glm::vec3(float(x)));
        image.set(x, 1, glm::vec3(float(x + 4)));
    }
    const Image half = boxDownsample(image, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_FLOAT_EQ(half.at(0, 0).r, (0 + 1 + 4 + 5) / 4.0f);
    EXPECT_FLOAT_EQ(half.at(1, 0).r, (2 + 3 + 6 + 7) / 4.0f);
}

TEST(ImageCompare, CountsFailingPixelsAndMeans) {
    Image a(10, 10), b(10, 10);
    b.set(3, 3, {1.0f, 0.0f, 0.0f});   // one pixel fully red: 255 steps in one channel
    const test::ImageDifference d = test::compareImages(a, b, 6);
    EXPECT_EQ(d.maxAbsDiff, 255);
    EXPECT_DOUBLE_EQ(d.failingFraction, 0.01);
    EXPECT_NEAR(d.meanAbsDiff, 255.0 / 300.0, 1e-9);
    EXPECT_TRUE(test::compareImages(a, Image(5, 5), 6).sizeMismatch);
    EXPECT_EQ(test::compareImages(a, a, 0).maxAbsDiff, 0);
}

} // namespace
} // namespace gi::core
