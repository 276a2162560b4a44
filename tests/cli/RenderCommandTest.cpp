// `voxatlas render` as users and CI run it: outputs, providers, and clean refusals of bad
// input (exit 2, one line naming what is wrong, no output file left behind).
#include "ImageCompare.h"
#include "Process.h"

#include "reference/ImageMetrics.h"
#include "core/ImageIO.h"
#include "core/Settings.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

int lineCount(const std::string& text) {
    return int(std::count(text.begin(), text.end(), '\n'));
}

// A refusal is exactly one line on stderr, exit status 2, and no output file.
void expectCleanRefusal(const ProcessResult& r, const std::string& mentions,
        const std::vector<std::string>& mustNotExist) {
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(mentions), std::string::npos) << "stderr should mention '" << mentions
                                                       << "': " << r.err;
    for (const std::string& path : mustNotExist) EXPECT_FALSE(fs::exists(path)) << path;
}

TEST(RenderCommand, WritesPngHdrAndTimings) {
    const std::string dir = makeTempDir("render-outputs");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--hdr",
            dir + "/a.exr", "--timings", dir + "/t.json", "--width", "96", "--height", "64",
            "--set", "render.frames=3"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Image png, exr;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/a.png", png, error)) << error;
    ASSERT_TRUE(core::readHdr(dir + "/a.exr", exr, error)) << error;
    EXPECT_EQ(png.width, 96);
    EXPECT_EQ(png.height, 64);
    EXPECT_EQ(exr.width, 96);
    EXPECT_TRUE(core::allFinite(exr));
    // The PNG is the HDR image encoded: identical after 8-bit sRGB quantisation.
    const ImageDifference d = compareImages(png, exr, 1);
    EXPECT_LE(d.maxAbsDiff, 1);

    std::ifstream json(dir + "/t.json");
    const nlohmann::json timings = nlohmann::json::parse(json);
    ASSERT_TRUE(timings.contains("passes"));
    bool sawForward = false;
    for (const auto& pass : timings["passes"]) {
        if (pass["name"] == "render/forward") {
            sawForward = true;
            EXPECT_EQ(pass["samples"], 3);
            EXPECT_GT(pass["gpu_ms_median"].get<double>(), 0.0);
        }
    }
    EXPECT_TRUE(sawForward);
    EXPECT_GT(timings["memory_bytes_total"].get<double>(), 0.0);
    fs::remove_all(dir);
}

// Each shadow method reports what it traces, its build and its memory; the timed passes
// include the build of the structure it needs.
TEST(RenderCommand, TimingsReportTheShadowMethodsStructures) {
    const std::string dir = makeTempDir("render-shadow-timings");
    const std::string emissive =
            std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box_emissive.gltf";
    struct Expected {
        const char* method;
        const char* structure;
        const char* pass;   // "" when the method has no pass of its own
    };
    for (const Expected& e : {Expected{"shadowmap", "a map per light", "render/shadow"},
                 // Every triangle casts: the box's 30 and the light panel's 2.
                 Expected{"bvh", "BVH over 32 triangles", "render/bvh/build"},
                 Expected{"voxel", "occupancy 32^3 x 3 levels", "voxel/voxelize"}}) {
        const ProcessResult r = runVoxatlas({"render", emissive, "--out", dir + "/a.png",
                "--timings", dir + "/t.json", "--width", "32", "--height", "32", "--set",
                std::string("shadow.method=") + e.method});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::ifstream json(dir + "/t.json");
        const nlohmann::json timings = nlohmann::json::parse(json);
        const nlohmann::json& shadows = timings["shadows"];
        EXPECT_EQ(shadows["method"], e.method);
        EXPECT_NE(shadows["structure"].get<std::string>().find(e.structure), std::string::npos)
                << shadows.dump();
        EXPECT_GT(shadows["bytes"].get<double>(), 0.0) << e.method;
        bool sawPass = false;
        for (const auto& pass : timings["passes"]) sawPass = sawPass || pass["name"] == e.pass;
        EXPECT_TRUE(sawPass) << e.method << " without " << e.pass;
        if (std::string(e.method) == "bvh") EXPECT_GT(shadows["build_ms"].get<double>(), 0.0);
    }
    fs::remove_all(dir);
}

TEST(RenderCommand, WritesPfm) {
    const std::string dir = makeTempDir("render-pfm");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--hdr",
            dir + "/a.pfm", "--width", "32", "--height", "32"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Image pfm;
    std::string error;
    ASSERT_TRUE(core::readHdr(dir + "/a.pfm", pfm, error)) << error;
    EXPECT_EQ(pfm.width, 32);
    fs::remove_all(dir);
}

// The two headless providers are both llvmpipe, so they should agree to the 8-bit tolerance
// of the golden-image tests (6/255 per channel, at most 0.2% of pixels over it).
TEST(RenderCommand, EglAndOSMesaAgree) {
    const std::string dir = makeTempDir("render-providers");
    for (const char* provider : {"egl", "osmesa"}) {
        const ProcessResult r = runVoxatlas({"render", kCornell, "--out",
                dir + "/" + provider + ".png", "--gl", provider, "--width", "128", "--height", "128"});
        ASSERT_EQ(r.exitCode, 0) << provider << ": " << r.err;
    }
    core::Image egl, osmesa;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/egl.png", egl, error)) << error;
    ASSERT_TRUE(core::readPng(dir + "/osmesa.png", osmesa, error)) << error;
    const ImageTolerance tolerance;
    const ImageDifference d = compareImages(egl, osmesa, tolerance.pixelThreshold);
    EXPECT_LE(d.failingFraction, tolerance.maxFailingFraction) << "maxAbsDiff " << d.maxAbsDiff;
    EXPECT_LE(d.meanAbsDiff, tolerance.maxMeanAbsDiff);
    fs::remove_all(dir);
}

TEST(RenderCommand, RejectsUnknownOption) {
    const std::string dir = makeTempDir("render-bad-option");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--frobnicate"}),
            "--frobnicate", {dir + "/a.png"});
}

TEST(RenderCommand, RejectsBadSetting) {
    const std::string dir = makeTempDir("render-bad-set");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--set",
                               "render.supersample=99"}),
            "render.supersample", {dir + "/a.png"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--set",
                               "no.such.key=1"}),
            "no.such.key", {dir + "/a.png"});
}

TEST(RenderCommand, RejectsLineSpaceOverBudgetOrOutOfRange) {
    const std::string dir = makeTempDir("render-linespace");
    // N = 10 at depth 4: 10^4 leaf voxels per axis, 10^12 bits before any line space.
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--set",
                               "shadow.method=linespace", "--set", "linespace.n=10", "--set",
                               "linespace.depth=4"}),
            "linespace.n 10", {dir + "/a.png"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--set",
                               "linespace.n=3"}),
            "linespace.n", {dir + "/a.png"});
}

// More voxelization samples a pixel than the OpenGL implementation offers (llvmpipe: 4;
// OpenGL 4.5 promises at least 4, so the test asks for 8 only where 8 is more than offered).
TEST(RenderCommand, RejectsVoxelizationSamplesBeyondTheImplementation) {
    const std::string dir = makeTempDir("render-msaa");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode",
            "voxel", "--set", "voxel.msaa=8"});
    if (r.exitCode == 0) GTEST_SKIP() << "this OpenGL offers 8 samples a pixel";
    expectCleanRefusal(r, "GL_MAX_FRAMEBUFFER_SAMPLES", {dir + "/a.png"});
}

TEST(RenderCommand, RejectsMissingScene) {
    const std::string dir = makeTempDir("render-missing");
    expectCleanRefusal(runVoxatlas({"render", dir + "/nothere.gltf", "--out", dir + "/a.png"}),
            "nothere.gltf", {dir + "/a.png"});
}

TEST(RenderCommand, RejectsUnwritableOutput) {
    const std::string dir = makeTempDir("render-unwritable");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/no/such/dir/a.png"}),
            "a.png", {dir + "/no/such/dir/a.png"});
    // A valid PNG path with an unwritable HDR path must not leave the PNG behind either.
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--hdr",
                               dir + "/missing/a.exr"}),
            "a.exr", {dir + "/a.png"});
}

TEST(RenderCommand, RejectsWrongExtensions) {
    const std::string dir = makeTempDir("render-extensions");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.jpg"}), ".png",
            {dir + "/a.jpg"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--hdr",
                               dir + "/a.hdr"}),
            ".exr", {dir + "/a.png", dir + "/a.hdr"});
}

TEST(RenderCommand, RejectsCameraOutOfRange) {
    const std::string dir = makeTempDir("render-camera");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--camera", "7"}),
            "camera", {dir + "/a.png"});
}

// Atlas GI renders (final and a debug view; both estimators), and its word-valued settings
// refuse unknown words cleanly. A small uncached atlas keeps it quick and out of ~/.cache.
TEST(RenderCommand, AtlasModeRenders) {
    const std::string dir = makeTempDir("render-atlas");
    for (const char* output : {"final", "atlas-charts"}) {
        const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode",
                "atlas", "--output", output, "--width", "48", "--height", "48", "--set",
                "atlas.resolution=128", "--set", "atlas.samples=16", "--set", "atlas.cache=0",
                "--set", "atlas.estimator=merz2010"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        core::Image image;
        std::string error;
        ASSERT_TRUE(core::readPng(dir + "/a.png", image, error)) << error;
        EXPECT_EQ(image.width, 48);
        double sum = 0.0;
        for (float value : image.rgb) sum += value;
        EXPECT_GT(sum, 0.0) << output;
        fs::remove(dir + "/a.png");
    }
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "atlas",
                               "--set", "atlas.estimator=guess"}),
            "atlas.estimator", {dir + "/a.png"});
}

TEST(RenderCommand, VplModeRendersAndRefusesBadSettings) {
    const std::string dir = makeTempDir("render-vpl");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode",
            "vpl", "--output", "indirect", "--width", "32", "--height", "32", "--set",
            "vpl.count=64", "--set", "vpl.visibility=none"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Image image;
    std::string error;
    ASSERT_TRUE(core::readPng(dir + "/a.png", image, error)) << error;
    double sum = 0.0;
    for (float value : image.rgb) sum += value;
    EXPECT_GT(sum, 0.0);
    fs::remove(dir + "/a.png");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "vpl",
                               "--set", "vpl.count=0"}),
            "vpl.count", {dir + "/a.png"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "vpl",
                               "--set", "vpl.clamp=-0.01"}),
            "vpl.clamp", {dir + "/a.png"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "vpl",
                               "--set", "vpl.visibility=octree"}),
            "vpl.visibility", {dir + "/a.png"});
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "vpl",
                               "--set", "vpl.visibility=svo", "--set", "vpl.svo_resolution=100"}),
            "vpl.svo_resolution", {dir + "/a.png"});
}

// An octree whose nodes would not fit vpl.svo_budget_mb is refused once its leaves are known:
// the Cornell box at 256^3 needs some 3 MiB of nodes.
TEST(RenderCommand, VplOctreeOverItsBudgetIsRefused) {
    const std::string dir = makeTempDir("render-vpl-svo");
    expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode", "vpl",
                               "--width", "16", "--height", "16", "--set", "vpl.count=16",
                               "--set", "vpl.visibility=svo", "--set", "vpl.svo_resolution=256",
                               "--set", "vpl.svo_budget_mb=1"}),
            "vpl.svo_budget_mb", {dir + "/a.png"});
}

// The path tracer through the same command: an image of each component, the direct part
// agreeing with the GPU's direct light, and a debug view refused as a GPU-only output.
TEST(RenderCommand, ReferenceModeWritesEachComponent) {
    const std::string dir = makeTempDir("render-reference");
    const std::vector<std::string> env = {"VOXATLAS_CACHE_DIR=" + dir + "/cache"};
    // The box's own light hangs 1 cm under the ceiling: two ceiling pixels next to it hold
    // half the direct energy of the frame, and how a pixel samples that 1/d^2 spike decides the
    // comparison. 13 cm under the ceiling (as AtlasReferenceGpuTest) no pixel dominates.
    const std::vector<std::string> light = {"--light", "none", "--light",
            "point:0.278,0.42,-0.15:1,1,1:0.3"};
    auto render = [&](std::vector<std::string> args, const std::vector<std::string>& extraEnv) {
        args.insert(args.begin(), {"render", kCornell, "--width", "32", "--height", "32"});
        args.insert(args.end(), light.begin(), light.end());
        return runVoxatlas(args, 120, extraEnv);
    };
    for (const char* output : {"final", "direct", "indirect"}) {
        const ProcessResult r = render({"--mode", "reference", "--output", output, "--out",
                dir + "/" + output + ".png", "--hdr", dir + "/" + output + ".pfm", "--set",
                "reference.spp=64"}, env);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    // The GPU's direct light of the same scene and camera: Lambertian like the reference
    // (material.specular=0), and 4x4 samples per pixel so that, like the reference's jittered
    // paths, it averages over the pixel square instead of sampling its centre.
    const ProcessResult gpu = render({"--mode", "direct", "--output", "direct", "--out",
            dir + "/gpu.png", "--hdr", dir + "/gpu.pfm", "--set", "material.specular=0", "--set",
            "render.supersample=4"}, {});
    ASSERT_EQ(gpu.exitCode, 0) << gpu.err;

    core::Image finalImage, direct, indirect, gpuDirect;
    std::string error;
    ASSERT_TRUE(core::readHdr(dir + "/final.pfm", finalImage, error)) << error;
    ASSERT_TRUE(core::readHdr(dir + "/direct.pfm", direct, error)) << error;
    ASSERT_TRUE(core::readHdr(dir + "/indirect.pfm", indirect, error)) << error;
    ASSERT_TRUE(core::readHdr(dir + "/gpu.pfm", gpuDirect, error)) << error;
    double sumIndirect = 0.0;
    for (std::size_t i = 0; i < finalImage.rgb.size(); ++i) {
        // final = direct + indirect, up to float rounding.
        EXPECT_NEAR(finalImage.rgb[i], direct.rgb[i] + indirect.rgb[i], 1e-4f + 1e-4f * finalImage.rgb[i]);
        sumIndirect += indirect.rgb[i];
    }
    EXPECT_GT(sumIndirect, 0.0);

    // Both are rho/pi * I * cos / d^2 from one point light, shadowed. The reference's direct
    // light has no Monte Carlo noise inside a surface (one shadow ray to a point light per
    // path), only where a pixel's jittered paths straddle an edge; what differs is the shadow
    // maps' PCF edges against ray-traced hard shadows, and a 4x4 grid against 64 jittered
    // positions at geometry edges. Measured: energy ratio 1.000, relative RMSE 2.6 % (at 256
    // spp the same, so it is not reference noise). A wrong convention (a missing pi, cos or
    // 1/d^2) is off by far more; so is sampling pixel centres only (5 % energy, 16 % RMSE).
    constexpr double kEnergyTolerance = 0.02;
    constexpr double kRmseTolerance = 0.06;
    const reference::ImageErrors errors = reference::measureImageError(gpuDirect, direct);
    EXPECT_NEAR(errors.energyRatio, 1.0, kEnergyTolerance) << "GPU / reference direct energy";
    EXPECT_LT(errors.relativeRmse, kRmseTolerance) << "relative RMSE of the GPU's direct light";

    expectCleanRefusal(render({"--mode", "reference", "--output", "voxel-albedo", "--out",
                               dir + "/x.png"}, env),
            "voxel-albedo", {dir + "/x.png"});
    fs::remove_all(dir);
}

// Every key `--set` documents is listed with its default value, as settingsHelp() formats
// it ("  key  default  help"). Hidden keys are developer switches left out on purpose.
TEST(RenderCommand, HelpListsEverySettingWithDefault) {
    const ProcessResult r = runVoxatlas({"render", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    const Settings defaults;
    for (const SettingSpec& spec : settingSpecs()) {
        const std::size_t line = r.out.find("\n  " + spec.key + " ");
        if (spec.hidden) {
            EXPECT_EQ(line, std::string::npos) << spec.key << " is hidden but listed";
            continue;
        }
        ASSERT_NE(line, std::string::npos) << spec.key << " missing from:\n" << r.out;
        std::istringstream fields(r.out.substr(line + 3 + spec.key.size()));
        std::string shownDefault;
        fields >> shownDefault;
        EXPECT_EQ(shownDefault, spec.get(defaults)) << spec.key;
    }
}

// vpl.bounces takes 1 or 2: no other count of VPL generations exists to honour.
TEST(RenderCommand, VplBouncesRefusesOtherCounts) {
    const std::string dir = makeTempDir("render-vpl-bounces");
    for (const char* bounces : {"0", "3", "-1", "two"}) {
        expectCleanRefusal(runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode",
                                   "vpl", "--set", std::string("vpl.bounces=") + bounces}),
                "vpl.bounces", {dir + "/a.png"});
    }
}

// The surface's light read picks faces of the light a cone meets: of anisotropic voxels, and of
// the light pyramid, which keeps them for isotropic voxels too, so voxel GI takes it with
// either kind. The VPLs' voxel occupancy traces no cones and takes the setting as it is.
TEST(RenderCommand, SurfaceLightReadRendersWithEitherKindOfVoxels) {
    const std::string dir = makeTempDir("render-light-read");
    for (const char* anisotropic : {"voxel.anisotropic=0", "voxel.anisotropic=1"}) {
        const ProcessResult voxel = runVoxatlas({"render", kCornell, "--out", dir + "/a.png",
                "--mode", "voxel", "--width", "32", "--height", "32", "--set",
                "voxel.light_read=surface", "--set", anisotropic});
        EXPECT_EQ(voxel.exitCode, 0) << anisotropic << ": " << voxel.err;
        EXPECT_TRUE(fs::exists(dir + "/a.png")) << anisotropic;
        fs::remove(dir + "/a.png");
    }
    const ProcessResult vpl = runVoxatlas({"render", kCornell, "--out", dir + "/b.png", "--mode",
            "vpl", "--width", "32", "--height", "32", "--set", "voxel.light_read=surface"});
    EXPECT_EQ(vpl.exitCode, 0) << vpl.err;
    EXPECT_EQ(vpl.err.find("voxel occupancy"), std::string::npos) << vpl.err;
    EXPECT_TRUE(fs::exists(dir + "/b.png"));
}

// The VPLs' visibility marches read only which voxels are occupied: with voxel.anisotropic=1 the
// occupancy still holds no directional copy (1.5 MiB for the Cornell box's 32^3 voxels).
TEST(RenderCommand, VplOccupancyKeepsNoDirectionalVoxels) {
    const std::string dir = makeTempDir("render-vpl-anisotropic");
    const ProcessResult r = runVoxatlas({"render", kCornell, "--out", dir + "/a.png", "--mode",
            "vpl", "--width", "32", "--height", "32", "--set", "voxel.anisotropic=1", "--timings",
            dir + "/t.json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream file(dir + "/t.json");
    const nlohmann::json timings = nlohmann::json::parse(file);
    ASSERT_TRUE(timings["memory_bytes"].contains("occupancy/voxel/normal"));
    EXPECT_FALSE(timings["memory_bytes"].contains("occupancy/voxel/directional"));
}

} // namespace
} // namespace gi::test
