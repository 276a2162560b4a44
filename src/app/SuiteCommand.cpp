#include "app/SuiteCommand.h"

#include "app/BenchCommon.h"
#include "app/SceneSetup.h"
#include "bench/AccuracyReport.h"
#include "bench/BenchRunner.h"
#include "platform/GlContext.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace gi::app {
namespace {

namespace fs = std::filesystem;

int fail(int status, const std::string& message) {
    std::fprintf(stderr, "voxatlas bench --suite: %s\n", message.c_str());
    return status;
}

std::vector<std::string> splitNames(const std::string& text) {
    std::vector<std::string> names;
    std::stringstream in(text);
    for (std::string name; std::getline(in, name, ',');) {
        if (!name.empty()) names.push_back(name);
    }
    return names;
}

std::string knownNames() {
    std::string names;
    for (const bench::SuiteScene& s : bench::suiteScenes()) {
        names += (names.empty() ? "" : ", ") + s.name;
    }
    return names;
}

// The suite's scenes, or those --scene names (comma-separated); Sponza's are left out with a
// note when it cannot be found, unless --scene asked for them.
bool selectScenes(const Config& config, std::vector<bench::SuiteScene>& scenes,
        std::vector<std::string>& notes, std::string& error) {
    const std::vector<std::string> wanted =
            config.sceneGiven ? splitNames(config.scenePath) : std::vector<std::string>{};
    for (const std::string& name : wanted) {
        bool known = false;
        for (const bench::SuiteScene& s : bench::suiteScenes()) known |= s.name == name;
        if (!known) {
            error = "--scene " + name + ": not a suite scene (" + knownNames() + ")";
            return false;
        }
    }
    const bool sponzaFound = fs::exists(sponzaPath());
    for (const bench::SuiteScene& s : bench::suiteScenes()) {
        const bool named = std::find(wanted.begin(), wanted.end(), s.name) != wanted.end();
        if (!wanted.empty() && !named) continue;
        if (bench::isSponzaScene(s) && !sponzaFound) {
            if (named) {
                error = s.name + ": Sponza not found at " + sponzaPath() +
                        " (set VOXATLAS_SPONZA)";
                return false;
            }
            notes.push_back(s.name + " left out: Sponza not found at " + sponzaPath() +
                            "; set VOXATLAS_SPONZA to include it");
            continue;
        }
        scenes.push_back(s);
    }
    return true;
}

// Loads a suite scene with its camera and lights, as `render` would from the same options.
bool loadSuiteScene(const Config& config, const bench::SuiteScene& suite, glm::ivec2 size,
        scene::Scene& scene, bench::BenchScene& benchScene, std::string& error) {
    Config sceneConfig = config;
    sceneConfig.scenePath = bench::isSponzaScene(suite)
            ? sponzaPath()
            : (fs::path(dataDirectory()) / suite.file).string();
    sceneConfig.cameraIndex = 0;
    sceneConfig.cameraSpec.reset();
    sceneConfig.extraLights.clear();
    sceneConfig.noLights = false;
    if (!applyOption(sceneConfig, "--camera", suite.camera, error)) return false;
    for (const std::string& light : suite.lights) {
        if (!applyOption(sceneConfig, "--light", light, error)) return false;
    }
    if (!loadScene(sceneConfig, scene, error)) return false;
    benchScene.name = suite.name;
    benchScene.path = displayPath(sceneConfig.scenePath);
    benchScene.cameraText = "camera " + suite.camera;
    benchScene.scene = &scene;
    benchScene.size = size;
    return selectCamera(sceneConfig, scene, float(size.x) / float(size.y), benchScene.camera,
            error);
}

// The settings under every configuration: the user's --set, surfaces the path tracer
// models too (Lambertian, or glTF's BRDF with --set material.model=gltf: the Phong model's
// highlight is the GPU's alone), and a reference with noise well under the errors it scores.
Settings suiteSettings(const Config& config, bench::SuiteSize size) {
    Settings base = config.settings;
    if (base.materialModel != MATERIAL_GLTF) base.specular = 0.0f;
    if (base.reference.spp == Settings{}.reference.spp) {
        base.reference.spp = size == bench::SuiteSize::Full ? 1024 : 256;
    }
    return base;
}

std::string commandText(const Config& config, bench::SuiteSize size) {
    std::string text = std::string("voxatlas bench --suite ") + bench::suiteSizeName(size);
    if (config.sceneGiven) text += " --scene " + config.scenePath;
    // Each --set the run was given, with the value it took (the last of a key given twice).
    std::vector<std::string> written;
    for (const std::string& key : config.settingKeys) {
        if (std::find(written.begin(), written.end(), key) != written.end()) continue;
        written.push_back(key);
        for (const SettingSpec& spec : settingSpecs()) {
            if (spec.key == key) text += " --set " + key + "=" + spec.get(config.settings);
        }
    }
    return text;
}

} // namespace

int runAccuracySuite(const Config& config) {
    const auto start = std::chrono::steady_clock::now();
    const bench::SuiteSize size = config.suite.value_or(bench::SuiteSize::Full);
    const std::string outDir = config.outDir.empty() ? "docs" : config.outDir;
    const bench::RunOptions options = size == bench::SuiteSize::Full
            ? bench::RunOptions{1, 3, 3}
            : bench::RunOptions{1, 1, 1};

    bench::SuiteRunInfo info;
    std::vector<bench::SuiteScene> scenes;
    std::string error;
    if (!selectScenes(config, scenes, info.notes, error)) return fail(2, error);
    for (const std::string& note : info.notes) std::fprintf(stderr, "voxatlas bench: %s\n",
            note.c_str());
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec || !fs::is_directory(outDir)) {
        return fail(2, "--out-dir " + outDir + ": cannot create the directory");
    }

    std::string notice;
    auto context = platform::createHeadlessContext(config.gl, !config.glExplicit, error, notice);
    if (!context) return fail(1, "no OpenGL 4.5 context: " + error);
    if (!notice.empty()) std::fprintf(stderr, "voxatlas bench: %s\n", notice.c_str());

    const Settings base = suiteSettings(config, size);
    const bench::BenchRunner runner(base, options);
    const int minFrames = options.warmupFrames + options.timedFrames;
    std::vector<bench::BenchProgress::PlannedRun> plan;
    for (const bench::SuiteScene& s : scenes) {
        for (const bench::BenchConfiguration& c :
                bench::suiteConfigurations(size, s, base, minFrames)) {
            plan.push_back({s.name, c.mode, c.costEstimate * (bench::isSponzaScene(s) ? 8 : 1)});
        }
    }
    std::printf("voxatlas bench --suite %s: %zu configurations on %zu scenes, %s\n",
            bench::suiteSizeName(size), plan.size(), scenes.size(),
            context->description().c_str());
    std::fflush(stdout);
    info.size = bench::suiteSizeName(size);
    info.command = commandText(config, size);
    info.glossy = base.glossyMaterials();
    info.date = localTime();
    info.glRenderer = context->description();
    info.loadBefore = loadAverage();

    bench::BenchProgress progress(plan, stdout);
    std::vector<bench::SuiteSceneResult> results;
    for (const bench::SuiteScene& suite : scenes) {
        scene::Scene scene;
        bench::BenchScene benchScene;
        if (!loadSuiteScene(config, suite, bench::suiteImageSize(size, suite), scene, benchScene,
                    error)) {
            return fail(2, suite.name + ": " + error);
        }
        benchScene.configurations = bench::suiteConfigurations(size, suite, base, minFrames);
        bench::SuiteSceneResult result;
        result.scene = suite;
        result.size = benchScene.size;
        result.reference = runner.reference(benchScene, error);
        if (result.reference.final.empty()) return fail(1, suite.name + ": reference: " + error);
        if (!runner.run(benchScene, result.reference, progress, result.measurements, error)) {
            return fail(1, suite.name + ": " + error);
        }
        results.push_back(std::move(result));
    }

    info.loadAfter = loadAverage();
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!bench::writeAccuracyReport(outDir, results, info, error)) return fail(1, error);
    int met = 0, targets = 0;
    for (const bench::SuiteScore& s : bench::scoreSuite(results)) {
        if (!s.target.any()) continue;
        ++targets;
        met += s.available && s.misses.empty();
    }
    std::printf("voxatlas bench --suite: %d of %d targets met in %d min %02d s; wrote "
                "%s/results-accuracy.md, accuracy.csv and images/accuracy_*.png\n",
            met, targets, int(info.seconds) / 60, int(info.seconds) % 60, outDir.c_str());
    return 0;
}

} // namespace gi::app
