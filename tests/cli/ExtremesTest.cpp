// Voxel GI at the ends of its parameter ranges: every run ends, with finite pixels, or is
// refused with exit 2 and one line before anything is allocated.
#include "Process.h"

#include "render/ImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace gi::test {
namespace {

const std::string kCornell = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

struct Extreme {
    const char* name;
    std::vector<std::string> settings;
};

class VoxelExtremes : public ::testing::TestWithParam<Extreme> {};

TEST_P(VoxelExtremes, EndsWithFinitePixels) {
    const std::string dir = makeTempDir(std::string("extreme-") + GetParam().name);
    std::vector<std::string> args = {"render", kCornell, "--mode", "voxel", "--out", dir + "/a.png",
            "--hdr", dir + "/a.pfm", "--width", "48", "--height", "48"};
    for (const std::string& s : GetParam().settings) {
        args.push_back("--set");
        args.push_back(s);
    }
    const ProcessResult r = runVoxatlas(args, 240);
    ASSERT_FALSE(r.timedOut) << "no spinlock or loop may hang";
    ASSERT_EQ(r.exitCode, 0) << r.err;
    render::Image image;
    std::string error;
    ASSERT_TRUE(render::readHdr(dir + "/a.pfm", image, error)) << error;
    EXPECT_TRUE(render::allFinite(image));
    std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Settings, VoxelExtremes,
        ::testing::Values(Extreme{"v4_l1", {"voxel.resolution=4", "voxel.cascades=1"}},
                Extreme{"v8_l8", {"voxel.resolution=8", "voxel.cascades=8"}},
                Extreme{"v128_l2", {"voxel.resolution=128", "voxel.cascades=2"}},
                Extreme{"multiplier1", {"voxel.multiplier=1"}},
                Extreme{"multiplier16", {"voxel.multiplier=16"}},
                Extreme{"trace_scale_1_16", {"voxel.trace_scale=0.0625"}},
                Extreme{"trace_scale_1", {"voxel.trace_scale=1"}},
                Extreme{"inject_4096", {"voxel.inject_resolution=1024"}},
                Extreme{"fragment_mean", {"voxel.inject_fragment_mean=1"}},
                Extreme{"no_filter_no_jitter", {"voxel.filter=0", "voxel.jitter=0"}},
                Extreme{"tiny_distance", {"voxel.max_distance=0.001"}},
                Extreme{"scene_centred", {"voxel.scene_centred=1", "voxel.coverage_max_axis=1"}}),
        [](const auto& info) { return std::string(info.param.name); });

// Irradiance far beyond the half-float range (65504) is clamped, never Inf, in the volume.
TEST(VoxelExtremesLight, HugeIntensityStaysFinite) {
    const std::string dir = makeTempDir("extreme-light");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--mode", "voxel", "--out",
            dir + "/a.png", "--hdr", dir + "/a.pfm", "--width", "32", "--height", "32", "--light",
            "point:0.278,0.3,-0.28:1,1,1:10000000"}, 240);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    render::Image image;
    std::string error;
    ASSERT_TRUE(render::readHdr(dir + "/a.pfm", image, error)) << error;
    EXPECT_TRUE(render::allFinite(image));
    std::filesystem::remove_all(dir);
}

// v = 256 with 8 levels would need 4 GiB: refused up front with one line, nothing written.
TEST(VoxelExtremesLight, OverBudgetCascadeIsRefused) {
    const std::string dir = makeTempDir("extreme-budget");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--mode", "voxel", "--out",
            dir + "/a.png", "--set", "voxel.resolution=256", "--set", "voxel.cascades=8"}, 60);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("budget"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/a.png"));
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace gi::test
