// `render --time` poses the scene's glTF animations; `info` reports them; bad times are
// refused with one line. `--light none` leaves a scene without any light.
#include "Process.h"

#include "core/ImageIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace gi::test {
namespace {

const std::string kAnimated =
        std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box_animated.gltf";

core::Image renderAt(const std::string& dir, const std::string& time,
        const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {"render", kAnimated, "--out", dir + "/t" + time + ".png",
            "--hdr", dir + "/t" + time + ".pfm", "--width", "48", "--height", "48", "--time", time};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult r = runVoxatlas(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    EXPECT_TRUE(core::readHdr(dir + "/t" + time + ".pfm", image, error)) << error;
    return image;
}

TEST(AnimationCommand, TimePosesTheAnimatedCube) {
    const std::string dir = makeTempDir("animation-time");
    const core::Image start = renderAt(dir, "0"), middle = renderAt(dir, "2"),
                        loop = renderAt(dir, "4");
    ASSERT_EQ(start.rgb.size(), middle.rgb.size());
    int changed = 0;
    for (std::size_t i = 0; i < start.rgb.size(); ++i) {
        changed += std::abs(start.rgb[i] - middle.rgb[i]) > 1e-3f * (1.0f + start.rgb[i]);
    }
    EXPECT_GT(changed, 30) << "the cube did not move between 0 s and 2 s";
    EXPECT_EQ(start.rgb, loop.rgb) << "the 4 s loop comes back to its start";
    std::filesystem::remove_all(dir);
}

TEST(AnimationCommand, InfoReportsAnimations) {
    const ProcessResult r = runVoxatlas({"info", kAnimated});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("animations 2, 4 s loop; 1 of 8 instances dynamic"), std::string::npos)
            << r.out;
}

TEST(AnimationCommand, BadTimesAreRefused) {
    for (const char* time : {"-1", "abc", "nan", "1e9"}) {
        const ProcessResult r = runVoxatlas({"render", kAnimated, "--out", "/tmp/never.png",
                "--time", time});
        EXPECT_EQ(r.exitCode, 2) << time << ": " << r.err;
        EXPECT_NE(r.err.find("--time"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

TEST(AnimationCommand, LightNoneRendersADarkScene) {
    const std::string dir = makeTempDir("light-none");
    const core::Image image = renderAt(dir, "0", {"--light", "none"});
    float brightest = 0.0f;
    for (float v : image.rgb) brightest = std::max(brightest, v);
    EXPECT_EQ(brightest, 0.0f) << "no scene light and no default light";
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace gi::test
