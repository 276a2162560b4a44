// `voxatlas render --exposure/--tonemap`: the PNG is exposed and tone mapped, the HDR image
// and a PNG without the options stay linear radiance at exposure 1.
#include "Process.h"

#include "core/ImageIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";
constexpr int kTimeout = 300;

std::string fileBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Renders the Cornell box at 64x64 to dir/name with `options`; the image read back.
core::Image render(const std::string& dir, const std::string& name,
        std::vector<std::string> options) {
    std::vector<std::string> args = {"render", kCornell, "--out", dir + "/" + name, "--width",
            "64", "--height", "64"};
    args.insert(args.end(), options.begin(), options.end());
    const ProcessResult r = runVoxatlas(args, kTimeout);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    EXPECT_TRUE(core::readPng(dir + "/" + name, image, error)) << error;
    return image;
}

double meanValue(const core::Image& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

TEST(ToneMapCommand, DefaultPngIsTheLinearHdrEncoded) {
    const std::string dir = makeTempDir("tonemap-default");
    (void)render(dir, "plain.png", {"--hdr", dir + "/plain.pfm"});
    (void)render(dir, "explicit.png", {"--exposure", "0", "--tonemap", "none"});
    EXPECT_EQ(fileBytes(dir + "/plain.png"), fileBytes(dir + "/explicit.png"));
    core::Image hdr;
    std::string error;
    ASSERT_TRUE(core::readHdr(dir + "/plain.pfm", hdr, error)) << error;
    ASSERT_TRUE(core::writePng(dir + "/encoded.png", hdr, error)) << error;
    EXPECT_EQ(fileBytes(dir + "/plain.png"), fileBytes(dir + "/encoded.png"));
    fs::remove_all(dir);
}

TEST(ToneMapCommand, ExposureBrightensAndDarkens) {
    const std::string dir = makeTempDir("tonemap-ev");
    const double plain = meanValue(render(dir, "plain.png", {}));
    const double brighter = meanValue(render(dir, "up.png", {"--exposure", "1"}));
    const double darker = meanValue(render(dir, "down.png", {"--exposure", "-1"}));
    EXPECT_GT(brighter, plain * 1.3);
    EXPECT_LT(darker, plain * 0.7);
    EXPECT_GT(darker, plain * 0.3);
    fs::remove_all(dir);
}

TEST(ToneMapCommand, AutoFilmicKeepsTheHdrLinear) {
    const std::string dir = makeTempDir("tonemap-auto");
    (void)render(dir, "plain.png", {"--hdr", dir + "/plain.pfm"});
    (void)render(dir, "auto.png",
            {"--exposure", "auto", "--tonemap", "filmic", "--hdr", dir + "/auto.pfm"});
    EXPECT_EQ(fileBytes(dir + "/plain.pfm"), fileBytes(dir + "/auto.pfm"));
    EXPECT_NE(fileBytes(dir + "/plain.png"), fileBytes(dir + "/auto.png"));
    fs::remove_all(dir);
}

TEST(ToneMapCommand, BadValuesAreOneLineExit2) {
    const std::string dir = makeTempDir("tonemap-bad");
    for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
                 {"--exposure", "x"}, {"--exposure", "99"}, {"--tonemap", "y"}}) {
        std::vector<std::string> args = {"render", kCornell, "--out", dir + "/a.png"};
        args.insert(args.end(), bad.begin(), bad.end());
        const ProcessResult r = runVoxatlas(args, kTimeout);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(bad[0]), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/a.png"));
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
