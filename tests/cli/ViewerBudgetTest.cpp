// The viewer's frame-time budget and its opening of dropped files, under Xvfb (ViewerRun.h):
// scripted camera motion (--move, --move-frames) holds the budget by lowering the render
// resolution, the still view afterwards converges to what `voxatlas render` makes of the same
// camera, and files dropped with --drop replace the scene or leave it with an error line.
#include "ImageCompare.h"
#include "ViewerRun.h"

#include "core/ImageIO.h"
#include "reference/ImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

class ViewerBudget : public ViewerWindowTest {};
class ViewerDrop : public ViewerWindowTest {};

// One group of the viewer's closing line "frame times (budget B ms): moving: N frames, median
// X ms, WxH to WxH; still: ...".
struct FrameGroup {
    int frames = 0;
    double medianMs = 0.0;
    int smallestWidth = 0;
};

FrameGroup frameGroup(const std::string& err, const std::string& group) {
    FrameGroup result;
    const std::size_t at = err.find(group + ": ");
    if (at == std::string::npos) return result;
    const std::string text = err.substr(at + group.size() + 2);
    result.frames = std::atoi(text.c_str());
    const std::size_t median = text.find("median ");
    if (median != std::string::npos) result.medianMs = std::atof(text.c_str() + median + 7);
    const std::size_t size = text.find(" ms, ");
    if (size != std::string::npos) result.smallestWidth = std::atoi(text.c_str() + size + 5);
    return result;
}

// The Cornell box's own camera as a --camera spec, and the same camera moved along +x.
std::string cornellCamera(float dx) {
    char text[96];
    std::snprintf(text, sizeof text, "%g,0.273,0.8,%g,0.273,-1,39.31", 0.278 + dx, 0.278 + dx);
    return text;
}

// The budget is half of what a still 640x480 frame takes on this machine, so holding it needs
// a lower resolution whatever the machine's speed; 20 frames move, the first ones included
// while the resolution adapts, and their median is what the test holds to +-30%.
TEST_F(ViewerBudget, MovingFramesHoldTheBudget) {
    const std::string dir = makeTempDir("view-budget");
    const std::vector<std::string> size = {"--width", "640", "--height", "480"};
    std::vector<std::string> still = {kViewerCornell, "--mode", "direct", "--frames", "6",
            "--set", "view.frame_budget_ms=0"};
    still.insert(still.end(), size.begin(), size.end());
    const ProcessResult calibrate = runView(dir, still);
    ASSERT_EQ(calibrate.exitCode, 0) << calibrate.err;
    const FrameGroup full = frameGroup(calibrate.err, "still");
    ASSERT_EQ(full.frames, 6) << calibrate.err;
    const double budget = std::round(full.medianMs / 2.0);

    std::vector<std::string> moving = {kViewerCornell, "--mode", "direct", "--frames", "24",
            "--move", "0.005,0,0", "--move-frames", "20", "--set",
            "view.frame_budget_ms=" + std::to_string(int(budget))};
    moving.insert(moving.end(), size.begin(), size.end());
    const ProcessResult r = runView(dir, moving);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const FrameGroup motion = frameGroup(r.err, "moving");
    // 20 frames that move and the one after (still rendered as moving).
    EXPECT_EQ(motion.frames, 21) << r.err;
    EXPECT_LT(motion.smallestWidth, 640) << "the resolution dropped: " << r.err;
    EXPECT_NEAR(motion.medianMs, budget, 0.3 * budget)
            << "still frames took " << full.medianMs << " ms; " << r.err;
    const FrameGroup after = frameGroup(r.err, "still");
    EXPECT_EQ(after.smallestWidth, 640) << "still frames are full resolution: " << r.err;
    fs::remove_all(dir);
}

// After 10 moving frames at a budget no frame meets (so at the smallest resolution), 14 still
// frames: the last one's linear radiance against `voxatlas render` of the moved camera. The
// atlas accumulates in texture space whatever the camera does and the voxel caches do not
// depend on the resolution, so both modes arrive at the headless image.
class ViewerConvergence : public ViewerWindowTest,
                          public ::testing::WithParamInterface<const char*> {};

TEST_P(ViewerConvergence, StillViewConvergesToTheHeadlessRender) {
    const std::string mode = GetParam();
    const std::string dir = makeTempDir("view-converge-" + mode);
    const std::vector<std::string> common = {"--mode", mode, "--width", "160", "--height",
            "120", "--set", "atlas.cache=0"};
    std::vector<std::string> view = {kViewerCornell, "--frames", "24", "--camera",
            cornellCamera(0.0f), "--move", "0.005,0,0", "--move-frames", "10", "--set",
            "view.frame_budget_ms=1", "--hdr", "v.pfm"};
    view.insert(view.end(), common.begin(), common.end());
    const ProcessResult r = runView(dir, view);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(frameGroup(r.err, "moving").smallestWidth, 20) << r.err;

    // As many frames as the viewer showed, so the atlas has summed as many sample sets.
    std::vector<std::string> render = {"render", kViewerCornell, "--camera", cornellCamera(0.05f),
            "--set", "render.frames=24", "--out", dir + "/r.png", "--hdr", dir + "/r.pfm"};
    render.insert(render.end(), common.begin(), common.end());
    const ProcessResult h = runVoxatlas(render, kViewerTimeoutSeconds);
    ASSERT_EQ(h.exitCode, 0) << h.err;

    core::Image shown, headless;
    std::string error;
    ASSERT_TRUE(core::readHdr(dir + "/v.pfm", shown, error)) << error;
    ASSERT_TRUE(core::readHdr(dir + "/r.pfm", headless, error)) << error;
    const reference::ImageErrors e = reference::measureImageError(shown, headless);
    ASSERT_FALSE(e.sizeMismatch);
    EXPECT_LT(e.relativeRmse, 0.02) << "energy ratio " << e.energyRatio;
    fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Modes, ViewerConvergence, ::testing::Values("voxel", "atlas"));

// A file whose node names a mesh it does not have: the loader refuses it in one line.
std::string writeBrokenScene(const std::string& dir) {
    const std::string path = dir + "/broken.gltf";
    std::ofstream(path) << R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],)"
                        << R"("nodes":[{"mesh":7}]})";
    return path;
}

core::Image readScreenshot(const std::string& path) {
    core::Image image;
    std::string error;
    EXPECT_TRUE(core::readPng(path, image, error)) << error;
    return image;
}

// Direct light: the pictures of separate runs are compared to the bit, and voxel GI's are not
// bit-identical across runs (voxelization order).
const std::vector<std::string> kDropView = {"--mode", "direct", "--frames", "5", "--width", "96",
        "--height", "72", "--exposure", "0", "--tonemap", "none", "--set", "view.frame_budget_ms=0"};

std::vector<std::string> dropArgs(const std::string& scene, const std::string& png,
        const std::vector<std::string>& extra) {
    std::vector<std::string> args = {scene, "--screenshot", png};
    args.insert(args.end(), kDropView.begin(), kDropView.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

TEST_F(ViewerDrop, BrokenFileLeavesTheSceneAndSaysWhy) {
    const std::string dir = makeTempDir("view-drop-broken");
    const std::string broken = writeBrokenScene(dir);
    const ProcessResult plain = runView(dir, dropArgs(kViewerCornell, "plain.png", {}));
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const ProcessResult r =
            runView(dir, dropArgs(kViewerCornell, "dropped.png", {"--drop", "1:" + broken}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("broken.gltf: nodes[0]: mesh 7 does not exist"),
            std::string::npos) << r.err;
    const ImageDifference d = compareImages(readScreenshot(dir + "/dropped.png"),
            readScreenshot(dir + "/plain.png"), 0);
    EXPECT_EQ(d.maxAbsDiff, 0) << "the Cornell box stays";
    fs::remove_all(dir);
}

TEST_F(ViewerDrop, GoodFileAfterABrokenOneReplacesTheScene) {
    const std::string dir = makeTempDir("view-drop-good");
    const std::string broken = writeBrokenScene(dir);
    const std::string rooms =
            std::string(VOXATLAS_DATA_DIR) + "/assets/scene_suite/two_rooms_thin_wall.gltf";
    const ProcessResult direct = runView(dir, dropArgs(rooms, "direct.png", {}));
    ASSERT_EQ(direct.exitCode, 0) << direct.err;
    const ProcessResult r = runView(dir, dropArgs(kViewerCornell, "dropped.png",
            {"--drop", "1:" + broken, "--drop", "2:" + rooms}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("opened " + rooms), std::string::npos) << r.err;
    // Opened as on the command line: the same camera, lights and picture.
    const ImageDifference d = compareImages(readScreenshot(dir + "/dropped.png"),
            readScreenshot(dir + "/direct.png"), 3);
    EXPECT_FALSE(d.sizeMismatch);
    EXPECT_LE(d.failingFraction, 0.002) << "max " << d.maxAbsDiff;
    fs::remove_all(dir);
}

TEST(ViewerDropInput, MalformedDropIsOneLineExit2) {
    const ProcessResult r = runVoxatlas({"view", kViewerCornell, "--frames", "1", "--drop",
            "scene.gltf"}, kViewerTimeoutSeconds);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--drop 'scene.gltf': expected FRAME:FILE"), std::string::npos)
            << r.err;
}

} // namespace
} // namespace gi::test
