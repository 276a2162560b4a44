// The stress matrix (ctest label `extremes`): every GI mode and the reference, at the ends of
// every quality setting and on scenes at the ends of scale, position, light and geometry.
// Each run is a `voxatlas render` process with a time limit (a spinlock hang fails instead of
// stalling CI); it must exit 0, write only finite, non-negative pixels, and its mean radiance
// must be plausible: the unmodified Cornell box's mean in the same mode times the factor the
// variant predicts (scaling geometry and light together changes nothing; radiance is linear in
// the light's intensity), within a band, or under an analytic ceiling. Settings outside their
// range must be refused with exit 2 and one line. Each outcome is also written to
// test-output/extremes/<case>.md for docs/results-extremes.md (scripts/extremes_report.sh).
#include "Process.h"
#include "SceneVariants.h"

#include "core/Image.h"
#include "core/ImageIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <unistd.h>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";
constexpr int kSize = 32;   // pixels per side: small, the matrix is about robustness

enum class Mode { Voxel, Atlas, Reference };

const char* modeName(Mode mode) {
    switch (mode) {
    case Mode::Voxel: return "voxel";
    case Mode::Atlas: return "atlas";
    case Mode::Reference: return "reference";
    }
    return "?";
}

// Settings every run shares: Lambertian materials (the ceilings assume them), a cheap but
// deterministic reference, and the thesis' allocation (render.plan=fixed), whose ends the
// cases push: voxel.cascades and atlas.resolution are values of the fixed plan only.
std::vector<std::string> baseArgs(Mode mode) {
    std::vector<std::string> args = {"--mode", modeName(mode), "--width", std::to_string(kSize),
            "--height", std::to_string(kSize), "--set", "material.specular=0", "--set",
            "render.plan=fixed"};
    if (mode == Mode::Reference) args.insert(args.end(), {"--set", "reference.spp=16"});
    if (mode == Mode::Atlas) args.insert(args.end(), {"--set", "atlas.resolution=256"});
    return args;
}

struct RunResult {
    ProcessResult process;
    double seconds = 0.0;
    bool imageRead = false;
    bool finite = false;
    double minimum = 0.0;
    double mean = 0.0;
};

RunResult renderOnce(const std::string& dir, const std::string& scene,
        const std::vector<std::string>& extra, const std::string& output, int timeoutSeconds) {
    fs::create_directories(dir);
    const std::string png = dir + "/" + output + ".png", pfm = dir + "/" + output + ".pfm";
    std::vector<std::string> args = {"render", scene, "--out", png, "--hdr", pfm, "--output", output};
    args.insert(args.end(), extra.begin(), extra.end());
    RunResult run;
    const auto start = std::chrono::steady_clock::now();
    run.process = runVoxatlas(args, timeoutSeconds, {"VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    core::Image image;
    std::string error;
    if (run.process.exitCode != 0 || !core::readHdr(pfm, image, error)) return run;
    run.imageRead = true;
    run.finite = core::allFinite(image);
    double sum = 0.0, lowest = 0.0;
    for (float v : image.rgb) {
        sum += v;
        lowest = std::min(lowest, double(v));
    }
    run.minimum = lowest;
    run.mean = image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
    return run;
}

// The unmodified Cornell box's mean radiance in one mode and component, computed once per
// build of the executable and kept in a file (the cases run as separate processes).
double baselineMean(Mode mode, const std::string& output) {
    const auto built = fs::last_write_time(VOXATLAS_EXECUTABLE).time_since_epoch().count();
    const std::string dir = std::string(VOXATLAS_TEST_OUTPUT_DIR) + "/extremes/baseline-" +
                            modeName(mode) + "-" + output + "-" + std::to_string(built);
    const std::string file = dir + ".txt";
    if (std::ifstream in(file); in) {
        double mean = 0.0;
        if (in >> mean) return mean;
    }
    const RunResult run = renderOnce(dir, kCornell, baseArgs(mode), output, 600);
    EXPECT_TRUE(run.imageRead) << "baseline failed: " << run.process.err;
    const std::string tmp = file + ".tmp." + std::to_string(::getpid());
    std::ofstream(tmp) << run.mean << "\n";
    fs::rename(tmp, file);
    return run.mean;
}

struct Case {
    std::string name;
    std::string description;
    std::vector<Mode> modes;
    // Writes the scene (if any) into `dir`; empty = the Cornell box.
    std::function<SceneVariant(const std::string& dir)> scene;
    std::vector<std::string> args;   // --set, --light, --camera ...
    double low = 0.5, high = 2.0;    // band around the predicted mean
    bool checkIndirect = false;      // also the indirect component against its baseline
    bool rejected = false;           // must exit 2 with one line naming `rejectKey`
    std::string rejectKey;
    int timeoutSeconds = 300;
};

std::vector<std::string> set(std::initializer_list<const char*> assignments) {
    std::vector<std::string> args;
    for (const char* a : assignments) args.insert(args.end(), {"--set", a});
    return args;
}

SceneVariant cornell(const std::string&) { return {kCornell, 1.0, 0.0}; }

const std::vector<Mode> kVoxel = {Mode::Voxel}, kAtlas = {Mode::Atlas},
                        kAll = {Mode::Voxel, Mode::Atlas, Mode::Reference};

std::vector<Case> cases() {
    std::vector<Case> c;
    // Quality settings at their ends (voxel).
    c.push_back({"v4", "voxel.resolution=4", kVoxel, cornell, set({"voxel.resolution=4"})});
    c.push_back({"v8", "voxel.resolution=8", kVoxel, cornell, set({"voxel.resolution=8"})});
    c.push_back({"v256_l1", "voxel.resolution=256, voxel.cascades=1", kVoxel, cornell,
            set({"voxel.resolution=256", "voxel.cascades=1"})});
    c.push_back({"l1", "voxel.cascades=1", kVoxel, cornell, set({"voxel.cascades=1"})});
    c.push_back({"l8", "voxel.cascades=8", kVoxel, cornell, set({"voxel.cascades=8"})});
    c.push_back({"multiplier1", "voxel.multiplier=1", kVoxel, cornell, set({"voxel.multiplier=1"})});
    c.push_back({"multiplier16", "voxel.multiplier=16", kVoxel, cornell,
            set({"voxel.multiplier=16"})});
    c.push_back({"trace1", "voxel.trace_scale=1", kVoxel, cornell, set({"voxel.trace_scale=1"})});
    c.push_back({"trace1_16", "voxel.trace_scale=1/16", kVoxel, cornell,
            set({"voxel.trace_scale=0.0625"})});
    c.push_back({"inject1024", "voxel.inject_resolution=1024", kVoxel, cornell,
            set({"voxel.inject_resolution=1024"})});
    c.push_back({"fragment_mean", "voxel.inject_fragment_mean=1 (the thesis' injection)", kVoxel,
            cornell, set({"voxel.inject_fragment_mean=1"}), 0.5, 4.0});
    c.push_back({"no_filter_no_jitter", "voxel.filter=0, voxel.jitter=0", kVoxel, cornell,
            set({"voxel.filter=0", "voxel.jitter=0"})});
    c.push_back({"tiny_distance", "voxel.max_distance=0.001", kVoxel, cornell,
            set({"voxel.max_distance=0.001"}), 0.3, 2.0});
    c.push_back({"scene_centred", "voxel.scene_centred=1, voxel.coverage_max_axis=1", kVoxel,
            cornell, set({"voxel.scene_centred=1", "voxel.coverage_max_axis=1"})});
    // Quality settings at their ends (atlas). 4096 samples at 4096^2 texels would be 7e10
    // gathers, hours on a CPU rasterizer: the sample extreme runs on a 256^2 atlas.
    c.push_back({"atlas16", "atlas.resolution=16", kAtlas, cornell, set({"atlas.resolution=16"})});
    c.push_back({"atlas4096", "atlas.resolution=4096", kAtlas, cornell,
            set({"atlas.resolution=4096"}), 0.5, 2.0, false, false, "", 900});
    c.push_back({"samples1", "atlas.samples=1", kAtlas, cornell, set({"atlas.samples=1"}),
            0.3, 3.0});
    c.push_back({"samples4096", "atlas.samples=4096", kAtlas, cornell,
            set({"atlas.samples=4096"}), 0.5, 2.0, false, false, "", 900});
    // Scenes at the extremes, in every mode.
    c.push_back({"scale_1em3", "Cornell box x 1e-3 (0.55 mm), light x 1e-6", kAll,
            [](const std::string& d) { return scaledCornell(d, 1e-3); }, {}, 0.8, 1.25});
    c.push_back({"scale_1e4", "Cornell box x 1e4 (5.5 km), light x 1e8", kAll,
            [](const std::string& d) { return scaledCornell(d, 1e4); }, {}, 0.8, 1.25});
    // Moving the whole scene changes nothing, once it is recentred (scene/Recentre.h): without
    // that, 8 mm float steps tore the walls and streaked the shadows (1.3-1.7 x the mean).
    c.push_back({"translated_1e5", "Cornell box and camera moved 1e5 m along x", kAll,
            [](const std::string& d) { return translatedCornell(d, 1e5); }, {}, 0.9, 1.1});
    c.push_back({"camera_1e5", "camera 1e5 m from the origin, looking at the box", kAll,
            [](const std::string&) { return SceneVariant{kCornell, 0.0, 0.0}; },
            {"--camera", "100000,0.27,100000,0.278,0.274,-0.28,1"}, 0.0, 0.0});
    c.push_back({"light_1em6", "light intensity 1e-6 cd", kAll,
            [](const std::string& d) { return cornellWithLightIntensity(d, 1e-6); }, {}, 0.5, 2.0,
            true});
    c.push_back({"light_1e7", "light intensity 1e7 cd", kAll,
            [](const std::string& d) { return cornellWithLightIntensity(d, 1e7); }, {}, 0.5, 2.0,
            true});
    c.push_back({"zero_lights", "no lights (--light none)", kAll,
            [](const std::string&) { return SceneVariant{kCornell, 0.0, 1e-9}; }, {"--light", "none"}});
    c.push_back({"lights_64", "64 point lights sharing the light's intensity", kAll,
            [](const std::string& d) { return cornellWithLightGrid(d, 64); }, {}, 0.25, 4.0});
    c.push_back({"degenerate", "zero-area, duplicate-vertex and needle triangles added", kAll,
            cornellWithDegenerateTriangles, {}, 0.8, 1.25});
    c.push_back({"single_triangle", "one triangle under a point light", kAll, singleTriangle, {}});
    c.push_back({"empty", "no nodes, no meshes", kAll, emptyScene, {}});
    // Out of range: refused before anything is rendered.
    c.push_back({"reject_v512", "voxel.resolution=512", kVoxel, cornell,
            set({"voxel.resolution=512"}), 0, 0, false, true, "voxel.resolution"});
    c.push_back({"reject_v12", "voxel.resolution=12 (not a power of two)", kVoxel, cornell,
            set({"voxel.resolution=12"}), 0, 0, false, true, "voxel.resolution"});
    c.push_back({"reject_trace", "voxel.trace_scale=0.01", kVoxel, cornell,
            set({"voxel.trace_scale=0.01"}), 0, 0, false, true, "voxel.trace_scale"});
    c.push_back({"reject_atlas8192", "atlas.resolution=8192", kAtlas, cornell,
            set({"atlas.resolution=8192"}), 0, 0, false, true, "atlas.resolution"});
    c.push_back({"reject_samples0", "atlas.samples=0", kAtlas, cornell, set({"atlas.samples=0"}),
            0, 0, false, true, "atlas.samples"});
    c.push_back({"reject_spp0", "reference.spp=0", {Mode::Reference}, cornell,
            set({"reference.spp=0"}), 0, 0, false, true, "reference.spp"});
    c.push_back({"reject_budget", "voxel.resolution=256, voxel.cascades=8 (4 GiB)", kVoxel,
            cornell, set({"voxel.resolution=256", "voxel.cascades=8"}), 0, 0, false, true,
            "budget"});
    c.push_back({"reject_shadow_budget", "64 point lights at shadow.resolution=8192 (96 GiB)",
            {Mode::Voxel}, [](const std::string& d) { return cornellWithLightGrid(d, 64); },
            set({"shadow.resolution=8192"}), 0, 0, false, true, "budget"});
    c.push_back({"reject_sun_map", "shadow.sun_resolution=16384", kVoxel, cornell,
            set({"shadow.sun_resolution=16384"}), 0, 0, false, true, "shadow.sun_resolution"});
    c.push_back({"reject_nan", "voxel.max_distance=nan", kVoxel, cornell,
            set({"voxel.max_distance=nan"}), 0, 0, false, true, "voxel.max_distance"});
    return c;
}

struct Param {
    Case c;
    Mode mode;
};

void PrintTo(const Param& p, std::ostream* os) { *os << p.c.name << " in " << modeName(p.mode); }

std::vector<Param> params() {
    std::vector<Param> p;
    for (const Case& c : cases()) {
        for (Mode mode : c.modes) p.push_back({c, mode});
    }
    return p;
}

std::string fmt(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

class ExtremesMatrix : public ::testing::TestWithParam<Param> {};

TEST_P(ExtremesMatrix, EndsFiniteAndPlausibleOrIsRefused) {
    const Case& c = GetParam().c;
    const Mode mode = GetParam().mode;
    const std::string id = c.name + "_" + modeName(mode);
    const std::string dir = std::string(VOXATLAS_TEST_OUTPUT_DIR) + "/extremes/" + id;
    fs::remove_all(dir);
    const SceneVariant scene = c.scene(dir);
    std::vector<std::string> args = baseArgs(mode);
    args.insert(args.end(), c.args.begin(), c.args.end());

    std::ostringstream row;   // one markdown table row for docs/results-extremes.md
    row << "| " << c.name << " | " << c.description << " | " << modeName(mode) << " | ";
    const RunResult run = renderOnce(dir, scene.path, args, "final", c.timeoutSeconds);
    ASSERT_FALSE(run.process.timedOut) << id << " did not finish in " << c.timeoutSeconds << " s";

    if (c.rejected) {
        EXPECT_EQ(run.process.exitCode, 2) << run.process.err;
        EXPECT_NE(run.process.err.find(c.rejectKey), std::string::npos) << run.process.err;
        const std::string err = run.process.err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << "one line: " << err;
        EXPECT_FALSE(fs::exists(dir + "/final.png"));
        row << "exit 2: `" << err.substr(0, err.find('\n')) << "` | | | " << fmt(run.seconds)
            << " |";
    } else {
        ASSERT_EQ(run.process.exitCode, 0) << run.process.err;
        ASSERT_TRUE(run.imageRead);
        EXPECT_TRUE(run.finite) << "non-finite pixels";
        EXPECT_GE(run.minimum, -1e-6 * std::max(run.mean, 1e-30)) << "negative radiance";
        std::string expectation;
        if (scene.radianceFactor > 0.0) {
            const double expected = baselineMean(mode, "final") * scene.radianceFactor;
            EXPECT_GE(run.mean, c.low * expected) << "mean radiance far below the prediction";
            EXPECT_LE(run.mean, c.high * expected) << "mean radiance far above the prediction";
            expectation = fmt(c.low * expected) + " .. " + fmt(c.high * expected);
        } else if (c.high > 0.0 || scene.ceiling > 0.0) {
            const double ceiling = scene.ceiling > 0.0 ? scene.ceiling : 0.0;
            EXPECT_LE(run.mean, ceiling) << "mean radiance above the analytic ceiling";
            EXPECT_GE(run.mean, scene.floor) << "a lit scene came out dark";
            expectation = scene.floor > 0.0 ? fmt(scene.floor) + " .. " + fmt(ceiling)
                                            : "<= " + fmt(ceiling);
        } else {
            // Not comparable (the box a few pixels wide): finite and non-negative is the test.
            expectation = "finite, >= 0";
        }
        std::string indirect;
        if (c.checkIndirect) {
            const RunResult ind = renderOnce(dir, scene.path, args, "indirect", c.timeoutSeconds);
            ASSERT_EQ(ind.process.exitCode, 0) << ind.process.err;
            EXPECT_TRUE(ind.finite);
            const double expected = baselineMean(mode, "indirect") * scene.radianceFactor;
            EXPECT_GE(ind.mean, c.low * expected) << "indirect light lost (underflow or clamp)";
            EXPECT_LE(ind.mean, c.high * expected) << "indirect light above the prediction";
            indirect = "; indirect " + fmt(ind.mean / expected) + " x predicted";
        }
        const bool ok = !::testing::Test::HasFailure();
        row << (ok ? "ok" : "FAILED") << indirect << " | " << fmt(run.mean) << " | "
            << expectation << " | " << fmt(run.seconds) << " |";
    }
    std::ofstream(std::string(VOXATLAS_TEST_OUTPUT_DIR) + "/extremes/" + id + ".md")
            << row.str() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Cases, ExtremesMatrix, ::testing::ValuesIn(params()),
        [](const auto& info) {
            return info.param.c.name + "_" + modeName(info.param.mode);
        });

} // namespace
} // namespace gi::test
