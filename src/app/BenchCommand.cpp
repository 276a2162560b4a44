#include "app/BenchCommand.h"

#include "app/BenchCommon.h"
#include "app/SceneSetup.h"
#include "app/SuiteCommand.h"
#include "app/TemporalCommand.h"
#include "bench/BenchReport.h"
#include "bench/BenchRunner.h"
#include "bench/BenchSweep.h"
#include "gl/GpuProfiler.h"
#include "platform/GlContext.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

namespace gi::app {
namespace {

namespace fs = std::filesystem;

// The camera DESIGN.md's Sponza measurements use: inside the atrium, looking down its length.
const CameraSpec kSponzaCamera{{0.0f, 2.0f, 14.0f}, {0.0f, 4.0f, -10.0f}, 60.0f};
constexpr const char* kSponzaCameraText = "camera 0,2,14,0,4,-10,60";
constexpr const char* kPython = "/usr/bin/python3";

int fail(int status, const std::string& message) {
    std::fprintf(stderr, "voxatlas bench: %s\n", message.c_str());
    return status;
}

struct LoadedScene {
    scene::Scene scene;
    bench::BenchScene bench;
};

// How much of the sweep runs and how many frames each configuration gets.
struct SweepPlan {
    bench::SweepSize size;
    bench::RunOptions run;
};

// The settings under every configuration: --set, then what the sweep itself fixes.
Settings baseSettings(const Config& config) {
    Settings base = config.settings;
    base.specular = 0.0f;
    // The sweep compares what each method costs per frame when everything moves: voxel GI
    // redoes every pass each frame, as the thesis does (docs/results-adaptive.md measures
    // what static caching saves).
    base.voxel.cache = false;
    // Its one-at-a-time rows set voxel.cascades and atlas.resolution, which the adaptive plan
    // would replace: the sweep varies the thesis' allocation unless render.plan is given.
    if (!config.plan.planGiven) base.plan = PLAN_FIXED;
    if (base.reference.spp == Settings{}.reference.spp) {
        base.reference.spp = config.sweep == bench::SweepSize::Full ? 256 : 64;
    }
    return base;
}

// Loads one scene with its camera, image size and configurations and appends it to `scenes`.
bool addScene(const Config& config, const SweepPlan& sweep, const std::string& path,
        const std::string& name, const std::optional<CameraSpec>& spec,
        const std::string& cameraText, glm::ivec2 quickSize,
        std::vector<std::unique_ptr<LoadedScene>>& scenes, std::string& error) {
    auto loaded = std::make_unique<LoadedScene>();
    Config sceneConfig = config;
    sceneConfig.scenePath = path;
    sceneConfig.cameraSpec = spec;
    sceneConfig.cameraIndex = 0;
    if (!loadScene(sceneConfig, loaded->scene, error)) return false;
    bench::BenchScene& b = loaded->bench;
    b.name = name;
    b.path = displayPath(path);
    b.cameraText = cameraText;
    b.scene = &loaded->scene;
    b.size = config.sweep == bench::SweepSize::Full ? quickSize * 2 : quickSize;
    const float aspect = float(b.size.x) / float(b.size.y);
    if (!selectCamera(sceneConfig, loaded->scene, aspect, b.camera, error)) return false;
    const glm::vec3 diagonal = loaded->scene.bounds.max - loaded->scene.bounds.min;
    b.configurations = bench::benchConfigurations({sweep.size,
            bench::shortMaxDistance(glm::length(diagonal)),
            sweep.run.warmupFrames + sweep.run.timedFrames});
    scenes.push_back(std::move(loaded));
    return true;
}

// The Cornell box, and the second scene unless it cannot be found (which is a note, not an
// error, unless --scene named it) or --scene names the Cornell box itself.
bool addScenes(const Config& config, const SweepPlan& sweep,
        std::vector<std::unique_ptr<LoadedScene>>& scenes, std::vector<std::string>& notes,
        std::string& error) {
    if (!addScene(config, sweep, defaultScenePath(), "cornell_box", std::nullopt, "camera 0",
                {128, 128}, scenes, error)) {
        return false;
    }
    const SceneChoice second = secondScene(config);
    std::error_code ec;
    const bool sameAsCornell = fs::exists(second.path) &&
                               fs::equivalent(second.path, defaultScenePath(), ec);
    if (sameAsCornell) return true;
    if (!second.explicitPath && !fs::exists(second.path)) {
        const std::string note = "Sponza not found at " + second.path +
                                 "; set VOXATLAS_SPONZA or pass --scene to include it";
        std::fprintf(stderr, "voxatlas bench: %s\n", note.c_str());
        notes.push_back(note);
        return true;
    }
    const bool sponza = isSponza(second.path);
    return addScene(config, sweep, second.path, fs::path(second.path).stem().string(),
            sponza ? std::optional<CameraSpec>(kSponzaCamera) : std::nullopt,
            sponza ? kSponzaCameraText : "camera 0", {160, 90}, scenes, error);
}

// What the report says about the run before it starts: sweep, machine, frame counts.
bench::BenchRunInfo runInfo(const Config& config, const SweepPlan& sweep,
        const platform::GlContext& context, const std::vector<std::string>& notes) {
    bench::BenchRunInfo info;
    info.sweep = bench::sweepSizeName(config.sweep);
    info.date = localTime();
    info.glRenderer = context.description();
    info.timing = gl::currentContextTimingMode() == gl::TimingMode::Finish
            ? "glFinish before and after each pass, wall clock (llvmpipe's timer queries miss "
              "its rasterizer threads)"
            : "GL timestamp queries";
    info.cores = int(std::thread::hardware_concurrency());
    info.warmupFrames = sweep.run.warmupFrames;
    info.timedFrames = sweep.run.timedFrames;
    info.scoredFrames = sweep.run.scoredFrames;
    info.notes = notes;
    info.loadBefore = loadAverage();
    return info;
}

// pareto.png from bench.csv; false (and no stale plot left behind) when the script fails.
bool plotPareto(const std::string& outDir) {
    const std::string csvPath = (fs::path(outDir) / "bench.csv").string();
    const std::string pngPath = (fs::path(outDir) / "pareto.png").string();
    std::string plotMessage;
    const bool plotted = bench::runPlotScript(kPython,
            (fs::path(dataDirectory()) / "scripts/plot_pareto.py").string(), csvPath, pngPath,
            plotMessage);
    if (!plotted) {
        // An older plot would no longer match the table.
        std::error_code ec;
        fs::remove(pngPath, ec);
        std::fprintf(stderr, "voxatlas bench: plot skipped: %s\n", plotMessage.c_str());
    }
    return plotted;
}

} // namespace

int runBench(const Config& config) {
    if (config.suite) return runAccuracySuite(config);
    if (config.temporal) return runTemporalBench(config);
    const auto start = std::chrono::steady_clock::now();
    const SweepPlan sweep{config.sweep,
            bench::RunOptions{2, config.sweep == bench::SweepSize::Full ? 7 : 3, 3}};
    const std::string outDir = config.outDir.empty() ? "docs/results" : config.outDir;

    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec || !fs::is_directory(outDir)) {
        return fail(2, "--out-dir " + outDir + ": cannot create the directory" +
                (ec ? " (" + ec.message() + ")" : ""));
    }

    const Settings base = baseSettings(config);
    std::vector<std::string> notes;
    std::vector<std::unique_ptr<LoadedScene>> scenes;
    std::string error;
    if (!addScenes(config, sweep, scenes, notes, error)) return fail(2, error);

    std::string notice;
    auto context = platform::createHeadlessContext(config.gl, !config.glExplicit, error, notice);
    if (!context) return fail(1, "no OpenGL 4.5 context: " + error);
    if (!notice.empty()) std::fprintf(stderr, "voxatlas bench: %s\n", notice.c_str());
    if (base.glDebug) platform::installDebugMessageLog();

    const bench::BenchRunner runner(base, sweep.run);
    bench::BenchRunInfo info = runInfo(config, sweep, *context, notes);

    std::vector<reference::ReferenceResult> references;
    std::vector<bench::BenchProgress::PlannedRun> plan;
    for (const auto& loaded : scenes) {
        references.push_back(runner.reference(loaded->bench, error));
        if (references.back().final.empty()) {
            return fail(1, "reference for " + loaded->bench.path + ": " + error);
        }
        const reference::ReferenceResult& r = references.back();
        info.scenes.push_back({loaded->bench.name, loaded->bench.path, loaded->bench.cameraText,
                loaded->bench.size, r.spp, r.bounces, r.noise.indirect, r.noise.final});
        for (const bench::BenchConfiguration& c : loaded->bench.configurations) {
            plan.push_back({loaded->bench.name, c.mode, c.costEstimate});
        }
    }
    const int total = int(plan.size());

    std::printf("voxatlas bench (%s): %d configurations on %zu scene(s), %s\n", info.sweep.c_str(),
            total, scenes.size(), info.glRenderer.c_str());
    std::fflush(stdout);
    bench::BenchProgress progress(plan, stdout);
    std::vector<bench::BenchMeasurement> measurements;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        if (!runner.run(scenes[i]->bench, references[i], progress, measurements, error)) {
            return fail(1, scenes[i]->bench.path + ": " + error);
        }
    }

    bench::finalizeMeasurements(measurements);
    info.loadAfter = loadAverage();
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!bench::writeBenchReport(outDir, measurements, info, error)) return fail(1, error);
    const bool plotted = plotPareto(outDir);

    int measured = 0;
    for (const bench::BenchMeasurement& m : measurements) measured += m.available ? 1 : 0;
    const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("voxatlas bench: %d of %d configurations measured in %d min %02d s; wrote "
                "%s/bench.csv, bench.md%s\n",
            measured, total, int(seconds) / 60, int(seconds) % 60, outDir.c_str(),
            plotted ? ", pareto.png" : " (no plot)");
    return measured > 0 ? 0 : 1;
}

} // namespace gi::app
