// The resource plan on the command line: `info` prints the adaptive (default) and the fixed plan
// with their bytes and why that plan is active; `render --move` times a moving camera (voxel.cache redoes the cascade as it
// moves); bad values are refused with one line and exit 2.
#include "Process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace gi::test {
namespace {

const std::string kBox = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

// Frames that ran voxel/voxelize, from a --timings report.
int voxelizeSamples(const std::string& timingsPath) {
    std::ifstream in(timingsPath);
    const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    if (!report.is_object() || !report.contains("passes")) {
        ADD_FAILURE() << timingsPath << ": no timings report";
        return -1;
    }
    for (const nlohmann::json& pass : report["passes"]) {
        if (pass["name"] == "voxel/voxelize") return pass["samples"].get<int>();
    }
    return 0;
}

TEST(ResourcePlanCommand, InfoPrintsBothPlans) {
    const ProcessResult adaptive = runVoxatlas({"info", kBox, "--set", "voxel.resolution=64"});
    ASSERT_EQ(adaptive.exitCode, 0) << adaptive.err;
    EXPECT_NE(adaptive.out.find("plan       adaptive (sized from the scene): the default"),
            std::string::npos) << adaptive.out;
    EXPECT_NE(adaptive.out.find("voxel    64^3 x 1 level, centred on the scene"), std::string::npos)
            << adaptive.out;
    EXPECT_NE(adaptive.out.find("lights   1 with shadow maps"), std::string::npos) << adaptive.out;
    EXPECT_TRUE(adaptive.err.empty()) << adaptive.err;
    const ProcessResult fixed = runVoxatlas({"info", kBox, "--set", "render.plan=fixed"});
    ASSERT_EQ(fixed.exitCode, 0) << fixed.err;
    EXPECT_NE(fixed.out.find("plan       fixed (the settings as given): render.plan=fixed was set"),
            std::string::npos) << fixed.out;
    EXPECT_NE(fixed.out.find("voxel    32^3 x 3 levels, centred on the camera"), std::string::npos)
            << fixed.out;
    EXPECT_NE(fixed.out.find("atlas    1024^2 texels"), std::string::npos) << fixed.out;
    EXPECT_TRUE(fixed.err.empty()) << fixed.err;
}

// The BVH that the atlas' and the VPLs' rays trace is in the plan, once for all of them, and
// only when one of them asks for it: the atlas' near field does by default.
TEST(ResourcePlanCommand, InfoPrintsTheBvhTheGiRaysTrace) {
    const ProcessResult all = runVoxatlas({"info", kBox, "--set", "atlas.visibility=bvh", "--set",
            "vpl.visibility=bvh"});
    ASSERT_EQ(all.exitCode, 0) << all.err;
    EXPECT_NE(all.out.find("GI rays: atlas.visibility=bvh, the atlas' near field (atlas.near_rays) "
                           "and vpl.visibility=bvh trace the BVH over "),
            std::string::npos) << all.out;
    const ProcessResult defaults = runVoxatlas({"info", kBox});
    ASSERT_EQ(defaults.exitCode, 0) << defaults.err;
    EXPECT_NE(defaults.out.find("GI rays: the atlas' near field (atlas.near_rays) traces the BVH "
                                "over "),
            std::string::npos) << defaults.out;
    const ProcessResult none = runVoxatlas({"info", kBox, "--set", "atlas.near_rays=0"});
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_EQ(none.out.find("GI rays"), std::string::npos) << none.out;
}

// A value for a key the adaptive plan sizes is what the user wants: it selects the fixed plan
// and says so on stderr, never silently replaced; with render.plan=adaptive it is refused.
TEST(ResourcePlanCommand, AKeyTheAdaptivePlanSizesSelectsTheFixedPlan) {
    const ProcessResult r = runVoxatlas({"info", kBox, "--set", "voxel.cascades=4"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("voxel.cascades set, so render.plan=fixed"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("plan       fixed (the settings as given): voxel.cascades set"),
            std::string::npos) << r.out;
    EXPECT_NE(r.out.find("32^3 x 4 levels"), std::string::npos) << r.out;
    const ProcessResult both = runVoxatlas(
            {"info", kBox, "--set", "voxel.cascades=4", "--set", "render.plan=adaptive"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_NE(both.err.find("--set voxel.cascades: render.plan=adaptive sizes it from the scene; "
                            "set render.plan=fixed to choose it"),
            std::string::npos) << both.err;
    EXPECT_TRUE(both.out.empty()) << both.out;
}

TEST(ResourcePlanCommand, InfoRefusesABadPlan) {
    const ProcessResult r = runVoxatlas({"info", kBox, "--set", "render.plan=huge"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("render.plan"), std::string::npos) << r.err;
}

TEST(ResourcePlanCommand, MovingCameraRevoxelizesOnlyWhenTheCascadeMoves) {
    const std::string dir = makeTempDir("plan-move");
    auto voxelizations = [&](const std::string& move, const std::string& cache,
                                 const std::string& plan = "fixed") {
        const std::string timings = dir + "/t" + move + cache + plan + ".json";
        const ProcessResult r = runVoxatlas({"render", kBox, "--mode", "voxel", "--out",
                dir + "/o.png", "--width", "32", "--height", "32", "--timings", timings, "--move",
                move, "--set", "render.frames=6", "--set", "voxel.cache=" + cache, "--set",
                "render.plan=" + plan});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return voxelizeSamples(timings);
    };
    EXPECT_EQ(voxelizations("0,0,0", "1"), 1) << "a still camera voxelizes once";
    EXPECT_EQ(voxelizations("0,0,0", "0"), 6) << "without the cache, every frame";
    // 30 cm per frame: beyond a coarsest voxel (8.5 cm), the cascade moves every frame.
    EXPECT_EQ(voxelizations("0,0,-0.3", "1"), 6);
    // The adaptive plan holds the whole box in one scene-centred level, which a camera moving
    // inside it never moves.
    EXPECT_EQ(voxelizations("0,0,-0.3", "1", "adaptive"), 1);
}

TEST(ResourcePlanCommand, PlayingAnAnimationRevoxelizesOnlyTheFramesItMoves) {
    const std::string animated =
            std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box_animated.gltf";
    const std::string dir = makeTempDir("plan-animate");
    auto voxelizations = [&](const std::string& step) {
        const std::string timings = dir + "/t" + step + ".json";
        const ProcessResult r = runVoxatlas({"render", animated, "--mode", "voxel", "--out",
                dir + "/o.png", "--width", "32", "--height", "32", "--timings", timings,
                "--animate", step, "--set", "render.frames=5"});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return voxelizeSamples(timings);
    };
    EXPECT_EQ(voxelizations("0"), 1) << "a still pose is voxelized once";
    EXPECT_EQ(voxelizations("0.05"), 5) << "the moving cube, every frame";
    const ProcessResult bad = runVoxatlas({"render", animated, "--out", dir + "/b.png", "--animate", "-1"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--animate '-1'"), std::string::npos) << bad.err;
}

TEST(ResourcePlanCommand, RejectsABadMove) {
    const std::string dir = makeTempDir("plan-move-bad");
    const ProcessResult r = runVoxatlas({"render", kBox, "--out", dir + "/o.png", "--move", "1,2"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--move '1,2'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/o.png"));
}

} // namespace
} // namespace gi::test
