// `voxatlas view` in a real GLFW window under Xvfb (xvfb-run, ViewerRun.h): scripted frames,
// injected hotkeys, screenshots, refusals of bad input, and the headless fallback without a
// display.
#include "ImageCompare.h"
#include "ViewerRun.h"
#include "core/Colour.h"

#include "core/ImageIO.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const std::string& kCornell = kViewerCornell;
constexpr int kTimeoutSeconds = kViewerTimeoutSeconds;

int lineCount(const std::string& text) {
    return int(std::count(text.begin(), text.end(), '\n'));
}

class ViewerTest : public ViewerWindowTest {};

// Mean of the sRGB-encoded channels, 0..1; a lit Cornell box is far from black.
float meanEncoded(const core::Image& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += core::linearToSrgb(v);
    return image.rgb.empty() ? 0.0f : float(sum / double(image.rgb.size()));
}

TEST_F(ViewerTest, ScriptedRunWritesScreenshotOfWindowSize) {
    const std::string dir = makeTempDir("view-frames");
    const ProcessResult r = runView(dir, {kCornell, "--frames", "3", "--screenshot", "s.png",
            "--width", "320", "--height", "240"});
    ASSERT_FALSE(r.timedOut);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/s.png", image, error)) << error;
    EXPECT_EQ(image.width, 320);
    EXPECT_EQ(image.height, 240);
    // The box's walls and light cover most of the frame: a mean encoded value above 0.05
    // (13/255) can only come from a rendered scene, not from a cleared or missing frame.
    EXPECT_GT(meanEncoded(image), 0.05f);
    fs::remove_all(dir);
}

TEST_F(ViewerTest, ScreenshotMatchesHeadlessRender) {
    const std::string dir = makeTempDir("view-vs-render");
    // The viewer's own look is auto exposure and a filmic curve; at exposure 0 and no curve
    // it shows the linear image `render` writes by default.
    const ProcessResult view = runView(dir, {kCornell, "--mode", "direct", "--frames", "2",
            "--screenshot", "v.png", "--width", "160", "--height", "120", "--exposure", "0",
            "--tonemap", "none"});
    ASSERT_EQ(view.exitCode, 0) << view.err;
    const ProcessResult render = runVoxatlas({"render", kCornell, "--out", dir + "/r.png",
            "--width", "160", "--height", "120"}, kTimeoutSeconds);
    ASSERT_EQ(render.exitCode, 0) << render.err;
    core::Image v, h;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/v.png", v, error)) << error;
    ASSERT_TRUE(core::readPng(dir + "/r.png", h, error)) << error;
    // Same renderer, camera and size on the same Mesa build; GLX and EGL contexts may differ in
    // rasterisation details only, so a few edge pixels may move by a step or two.
    const ImageDifference d = compareImages(v, h, 3);
    EXPECT_FALSE(d.sizeMismatch);
    EXPECT_LE(d.failingFraction, 0.002) << "max " << d.maxAbsDiff << " mean " << d.meanAbsDiff;
    fs::remove_all(dir);
}

TEST_F(ViewerTest, InjectedHotkeysRun) {
    const std::string dir = makeTempDir("view-keys");
    const ProcessResult r = runView(dir, {kCornell, "--frames", "4", "--width", "200",
            "--height", "150", "--keys", "1:H,2:O,2:V,3:C,3:R"});
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    fs::remove_all(dir);
}

// C moves to the next camera (the Cornell box's own, then the default one chosen from the
// geometry), which shows another picture; Home comes back to the exact start view.
TEST_F(ViewerTest, CameraKeysCycleAndHomeReturnsToTheStart) {
    const std::string dir = makeTempDir("view-cameras");
    // Direct light: two runs of voxel GI differ in the last bits (voxelization order).
    const std::vector<std::string> size = {"--width", "64", "--height", "64", "--exposure", "0",
            "--mode", "direct"};
    auto run = [&](const std::string& keys, const std::string& png) {
        std::vector<std::string> args = {kCornell, "--frames", "3", "--screenshot", png};
        args.insert(args.end(), size.begin(), size.end());
        if (!keys.empty()) args.insert(args.end(), {"--keys", keys});
        const ProcessResult r = runView(dir, args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        core::Image image;
        std::string error;
        EXPECT_TRUE(core::readPng(dir + "/" + png, image, error)) << error;
        return image;
    };
    const core::Image start = run("", "start.png");
    const core::Image next = run("1:C", "next.png");
    const core::Image home = run("0:C,1:HOME", "home.png");
    EXPECT_GT(compareImages(next, start, 3).failingFraction, 0.1) << "C changed the view";
    EXPECT_EQ(compareImages(home, start, 3).maxAbsDiff, 0) << "Home is the start view";
    fs::remove_all(dir);
}

// Key 2 switches to voxel GI, key 3 to atlas GI (a small atlas, uncached, to stay quick and
// out of the user's cache); the indirect light brightens the frame.
TEST_F(ViewerTest, ModeKeysSwitchOrExplain) {
    const std::string dir = makeTempDir("view-modes");
    // Fixed exposure: auto exposure would bring both frames to the same brightness.
    const ProcessResult direct = runView(dir, {kCornell, "--mode", "direct", "--frames", "2",
            "--width", "64", "--height", "64", "--screenshot", "direct.png", "--exposure", "0",
            "--tonemap", "none"});
    ASSERT_EQ(direct.exitCode, 0) << direct.err;
    const ProcessResult r = runView(dir, {kCornell, "--mode", "direct", "--frames", "3",
            "--width", "64", "--height", "64", "--keys", "0:2,1:3", "--screenshot", "s.png", "--set",
            "atlas.resolution=256", "--set", "atlas.cache=0", "--exposure", "0", "--tonemap",
            "none"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("is not available"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("atlas: 15 charts"), std::string::npos) << "key 3 builds the atlas: " << r.err;
    core::Image withGi, withoutGi;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/s.png", withGi, error)) << error;
    ASSERT_TRUE(core::readPng(dir + "/direct.png", withoutGi, error)) << error;
    double sumGi = 0.0, sumDirect = 0.0;
    for (float value : withGi.rgb) sumGi += value;
    for (float value : withoutGi.rgb) sumDirect += value;
    EXPECT_GT(sumGi, sumDirect * 1.02) << "atlas GI adds indirect light to the frame";
    fs::remove_all(dir);
}

// Two presses of = raise the exposure by one stop; - lowers it; X and T toggle auto exposure
// and the curve without failing.
TEST_F(ViewerTest, ExposureKeysStepTheExposure) {
    const std::string dir = makeTempDir("view-exposure");
    const std::vector<std::string> base = {kCornell, "--frames", "3", "--width", "64",
            "--height", "64", "--exposure", "-1", "--tonemap", "none"};
    auto shot = [&](const std::string& keys, const std::string& name) {
        std::vector<std::string> args = base;
        for (const char* arg : {"--keys", keys.c_str(), "--screenshot", name.c_str()}) {
            args.push_back(arg);
        }
        const ProcessResult r = runView(dir, args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        core::Image image;
        std::string error;
        EXPECT_TRUE(core::readPng(dir + "/" + name, image, error)) << error;
        return image;
    };
    const core::Image plain = shot("0:T,1:T", "plain.png");
    const core::Image brighter = shot("1:=,1:=", "brighter.png");
    const core::Image darker = shot("1:-,1:-", "darker.png");
    const core::Image toggled = shot("1:X,2:X", "toggled.png");
    EXPECT_GT(meanEncoded(brighter), meanEncoded(plain) * 1.1f);
    EXPECT_LT(meanEncoded(darker), meanEncoded(plain) * 0.9f);
    EXPECT_GT(meanEncoded(toggled), 0.0f);
    fs::remove_all(dir);
}

TEST_F(ViewerTest, F12WritesNumberedScreenshot) {
    const std::string dir = makeTempDir("view-f12");
    const ProcessResult r = runView(dir, {kCornell, "--frames", "3", "--width", "128",
            "--height", "96", "--keys", "1:F12,2:F12"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"voxatlas-1.png", "voxatlas-2.png"}) {
        core::Image image;
        std::string error;
        ASSERT_TRUE(core::readPng(dir + "/" + name, image, error)) << error;
        EXPECT_EQ(image.width, 128);
        EXPECT_EQ(image.height, 96);
    }
    fs::remove_all(dir);
}

TEST_F(ViewerTest, EscapeQuitsAndStillSavesTheLastFrame) {
    const std::string dir = makeTempDir("view-escape");
    const ProcessResult r = runView(dir, {kCornell, "--frames", "50", "--width", "64",
            "--height", "64", "--keys", "2:ESCAPE", "--screenshot", "s.png"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/s.png"));
    fs::remove_all(dir);
}

// Input is checked before any window opens, so these need no display.
TEST(ViewerInput, BadScenePathIsOneLineExit2) {
    const std::string dir = makeTempDir("view-bad-scene");
    const ProcessResult r = runVoxatlas({"view", dir + "/missing.gltf", "--frames", "1"},
            kTimeoutSeconds);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("missing.gltf"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(ViewerInput, UnknownInjectedKeyIsOneLineExit2) {
    const ProcessResult r = runVoxatlas({"view", kCornell, "--frames", "1", "--keys", "0:NOPE"},
            kTimeoutSeconds);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("NOPE"), std::string::npos) << r.err;
}

TEST(ViewerInput, UnwritableScreenshotIsOneLineExit2) {
    const ProcessResult r = runVoxatlas({"view", kCornell, "--frames", "1", "--screenshot",
            "/nonexistent-dir/s.png"}, kTimeoutSeconds);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("/nonexistent-dir/s.png"), std::string::npos) << r.err;
}

// No X server at all: the viewer says why in one line, with the screenshot's full path, and
// renders what `voxatlas render` would, in the mode the viewer was asked to start in.
TEST(ViewerNoDisplay, FallsBackToHeadlessScreenshot) {
    const std::string dir = makeTempDir("view-no-display");
    const ProcessResult r = runProcess({"/usr/bin/env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY",
            "-C", dir, VOXATLAS_EXECUTABLE, "view", kCornell, "--mode", "voxel", "--screenshot",
            "x.png", "--width", "96", "--height", "72"}, kTimeoutSeconds);
    ASSERT_FALSE(r.timedOut);
    EXPECT_NE(r.err.find("voxatlas view: no display ("), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("rendering a headless screenshot instead: " + dir + "/x.png"),
            std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(96x72, voxel,"), std::string::npos) << "not in voxel mode: " << r.err;
    if (r.exitCode == 1 && r.err.find("no OpenGL 4.5 context") != std::string::npos) {
        GTEST_SKIP() << "no headless OpenGL context either: " << r.err;
    }
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/x.png", image, error)) << error;
    EXPECT_EQ(image.width, 96);
    EXPECT_EQ(image.height, 72);
    fs::remove_all(dir);
}

// Without --mode and --screenshot: voxel GI (the viewer opens with global illumination) into
// voxatlas-view.png.
TEST(ViewerNoDisplay, DefaultsAreVoxelModeAndVoxatlasViewPng) {
    const std::string dir = makeTempDir("view-no-display-default");
    const ProcessResult r = runProcess({"/usr/bin/env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY",
            "-C", dir, VOXATLAS_EXECUTABLE, "view", kCornell, "--width", "32", "--height", "32"},
            kTimeoutSeconds);
    if (r.exitCode == 1 && r.err.find("no OpenGL 4.5 context") != std::string::npos) {
        GTEST_SKIP() << "no headless OpenGL context: " << r.err;
    }
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("voxatlas-view.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(32x32, voxel,"), std::string::npos) << "not in voxel mode: " << r.err;
    EXPECT_TRUE(fs::exists(dir + "/voxatlas-view.png"));
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
