#include "app/TemporalCommand.h"

#include "app/BenchCommon.h"
#include "app/SceneSetup.h"
#include "bench/TemporalReport.h"
#include "platform/GlContext.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace gi::app {
namespace {

namespace fs = std::filesystem;

int fail(int status, const std::string& message) {
    std::fprintf(stderr, "voxatlas bench --temporal: %s\n", message.c_str());
    return status;
}

// The sizes and frame counts of one form of the run.
struct TemporalForm {
    bool quick = false;
    glm::ivec2 size{0};
    int sponzaFrames = 0, cornellFrames = 0;
    int settleFrames = 0, movingFrames = 0;
};

TemporalForm formFor(const Config& config) {
    if (config.sweep != bench::SweepSize::Full) return {true, {128, 72}, 0, 6, 2, 3};
    // 32 frames (3.2 m) cross at least one snap of Sponza's coarsest voxel (2.56 m).
    return {false, {256, 144}, 32, 24, 4, 8};
}

// The atrium view the bench's other Sponza measurements use, walking towards its far end.
const CameraSpec kSponzaCamera{{0.0f, 2.0f, 14.0f}, {0.0f, 4.0f, -10.0f}, 60.0f};
constexpr float kSponzaStep = 0.10f;    // m per frame
constexpr float kCornellStep = 0.005f;  // m per frame, about 1 % of the box's width

struct LoadedPath {
    scene::Scene scene;
    bench::TemporalPathResult result;
};

bool loadPath(const Config& config, const std::string& path, const std::optional<CameraSpec>& spec,
        glm::ivec2 size, scene::Scene& scene, scene::CameraView& camera, std::string& error) {
    Config sceneConfig = config;
    sceneConfig.scenePath = path;
    sceneConfig.cameraSpec = spec;
    sceneConfig.cameraIndex = 0;
    sceneConfig.sceneGiven = true;
    return loadScene(sceneConfig, scene, error) &&
           selectCamera(sceneConfig, scene, float(size.x) / float(size.y), camera, error);
}

// The paths of this form: Sponza's walk when the file is there, the Cornell box sideways.
bool loadPaths(const Config& config, const TemporalForm& form,
        std::vector<std::unique_ptr<LoadedPath>>& paths, std::vector<std::string>& notes,
        std::string& error) {
    if (!form.quick) {
        const std::string sponza = sponzaPath();
        if (!fs::exists(sponza)) {
            const std::string note = "Sponza walk skipped: Sponza not found at " + sponza +
                                     " (set VOXATLAS_SPONZA to include it)";
            std::fprintf(stderr, "voxatlas bench --temporal: %s\n", note.c_str());
            notes.push_back(note);
        } else {
            auto loaded = std::make_unique<LoadedPath>();
            bench::TemporalPath& p = loaded->result.path;
            if (!loadPath(config, sponza, kSponzaCamera, form.size, loaded->scene, p.start,
                        error)) {
                return false;
            }
            p.name = "sponza_walk";
            p.description = "Sponza, walking down the atrium at 10 cm per frame from the bench's "
                            "atrium view (camera 0,2,14 towards 0,4,-10, 60°)";
            p.scenePath = displayPath(sponza);
            p.step = glm::vec3(0.0f, 0.0f, -kSponzaStep);
            p.frames = form.sponzaFrames;
            paths.push_back(std::move(loaded));
        }
    }
    auto loaded = std::make_unique<LoadedPath>();
    bench::TemporalPath& p = loaded->result.path;
    if (!loadPath(config, defaultScenePath(), std::nullopt, form.size, loaded->scene, p.start,
                error)) {
        return false;
    }
    p.name = "cornell_sideways";
    p.description = "The Cornell box from its camera, moving sideways (to the camera's right) "
                    "at 5 mm per frame";
    p.scenePath = displayPath(defaultScenePath());
    const glm::vec3 right(p.start.view[0][0], p.start.view[1][0], p.start.view[2][0]);
    p.step = glm::normalize(right) * kCornellStep;
    p.frames = form.cornellFrames;
    paths.push_back(std::move(loaded));
    for (auto& path : paths) {
        path->result.path.scene = &path->scene;
        path->result.path.size = form.size;
        // The atlas reaches its 1024 progressive samples in 11 frames of 100.
        path->result.path.warmupFrames = 11;
    }
    return true;
}

std::vector<bench::TemporalConfiguration> configurations(const Settings& base, bool quick) {
    // The plain rows switch the (default) filter off.
    Settings plain = base;
    plain.temporal.filter = false;
    Settings filtered = base;
    filtered.temporal.filter = true;
    Settings unclamped = filtered;
    unclamped.temporal.clamp = false;
    std::vector<bench::TemporalConfiguration> list;
    for (render::GiMode mode : {render::GiMode::Voxel, render::GiMode::Atlas}) {
        const std::string name = render::giModeName(mode);
        list.push_back({name, mode, plain});
        list.push_back({name + " + filter", mode, filtered});
        if (!quick) list.push_back({name + " + filter, no clamp", mode, unclamped});
    }
    if (quick) return list;
    // VPLs drawn by the view's importance are drawn anew as the camera moves: the full form
    // sets them beside the draw by flux alone, which keeps its VPLs.
    Settings byFlux = plain;
    byFlux.vpl.importance = false;
    list.push_back({"vpl", render::GiMode::Vpl, plain});
    list.push_back({"vpl + filter", render::GiMode::Vpl, filtered});
    list.push_back({"vpl, drawn by flux alone", render::GiMode::Vpl, byFlux});
    return list;
}

bool runPaths(std::vector<std::unique_ptr<LoadedPath>>& paths,
        const std::vector<bench::TemporalConfiguration>& list, const Settings& base,
        gl::ShaderLibrary& shaders, std::string& error) {
    for (auto& loaded : paths) {
        bench::TemporalPathResult& result = loaded->result;
        std::vector<bench::CoveredFrame> direct;
        if (!bench::renderDirectPath(result.path, base, shaders, direct, error)) return false;
        for (int frame : bench::stripFrames(result.path.frames)) {
            result.directStrip.push_back(direct[std::size_t(frame)].image);
        }
        for (const bench::TemporalConfiguration& c : list) {
            bench::FlickerMeasurement m;
            if (!bench::measureFlicker(result.path, c, direct, shaders, m, error)) {
                error = result.path.name + ", " + c.label + ": " + error;
                return false;
            }
            std::printf("%s, %s: indirect change %.2f %%, direct %.2f %%, ratio %.2f (%.1f s)\n",
                    result.path.name.c_str(), c.label.c_str(), 100.0 * m.indirectChange,
                    100.0 * m.directChange,
                    m.directChange > 0 ? m.indirectChange / m.directChange : 0.0,
                    m.seconds);
            std::fflush(stdout);
            result.measurements.push_back(std::move(m));
        }
    }
    return true;
}

bool runGhost(const Config& config, const TemporalForm& form,
        const std::vector<bench::TemporalConfiguration>& list, gl::ShaderLibrary& shaders,
        scene::Scene& scene, bench::TemporalGhostResult& ghost, std::string& error) {
    const std::string path =
            (fs::path(dataDirectory()) / "assets/cornell_box/cornell_box_animated.gltf").string();
    bench::GhostSetup& s = ghost.setup;
    if (!loadPath(config, path, std::nullopt, form.size, scene, s.camera, error)) return false;
    s.scene = &scene;
    s.scenePath = displayPath(path);
    s.size = form.size;
    s.startTime = 0.5f;
    s.stepSeconds = 0.1f;   // 2 cm of the cube's slide per frame
    s.settleFrames = form.settleFrames;
    s.movingFrames = form.movingFrames;
    for (const bench::TemporalConfiguration& c : list) {
        bench::GhostMeasurement m;
        if (!bench::measureGhosting(s, c, shaders, m, error)) {
            error = "moving cube, " + c.label + ": " + error;
            return false;
        }
        std::printf("moving cube, %s: trail after %d frames %.2f %% of the floor's light\n",
                c.label.c_str(), s.holdFrames, m.trail.empty() ? 0.0 : 100.0 * m.trail.back());
        std::fflush(stdout);
        ghost.measurements.push_back(std::move(m));
    }
    return true;
}

} // namespace

int runTemporalBench(const Config& config) {
    const auto start = std::chrono::steady_clock::now();
    const TemporalForm form = formFor(config);
    const std::string outDir = config.outDir.empty() ? "docs" : config.outDir;
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec || !fs::is_directory(outDir)) {
        return fail(2, "--out-dir " + outDir + ": cannot create it");
    }

    Settings base = config.settings;
    base.specular = 0.0f;
    std::vector<std::string> notes;
    std::vector<std::unique_ptr<LoadedPath>> paths;
    std::string error;
    if (!loadPaths(config, form, paths, notes, error)) return fail(2, error);

    std::string notice;
    auto context = platform::createHeadlessContext(config.gl, !config.glExplicit, error, notice);
    if (!context) return fail(1, "no OpenGL 4.5 context: " + error);
    if (!notice.empty()) std::fprintf(stderr, "voxatlas bench --temporal: %s\n", notice.c_str());

    gl::ShaderLibrary shaders;
    const std::vector<bench::TemporalConfiguration> list = configurations(base, form.quick);
    if (!runPaths(paths, list, base, shaders, error)) return fail(1, error);
    scene::Scene animated;
    bench::TemporalGhostResult ghost;
    if (!runGhost(config, form, list, shaders, animated, ghost, error)) return fail(1, error);

    bench::TemporalRunInfo info;
    info.command = std::string("voxatlas bench --temporal") + (form.quick ? " --quick" : "") +
                   (config.outDir.empty() ? "" : " --out-dir " + config.outDir);
    info.form = form.quick ? "quick" : "full";
    info.date = localTime();
    info.glRenderer = context->description();
    info.notes = notes;
    info.blend = base.temporal.blend;
    info.blendMoving = base.temporal.blendMoving;
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<bench::TemporalPathResult> results;
    for (auto& loaded : paths) results.push_back(loaded->result);
    if (!bench::writeTemporalReport(outDir, results, ghost, info, error)) return fail(1, error);
    std::printf("voxatlas bench --temporal: wrote %s/results-temporal.md in %.0f s\n",
            outDir.c_str(), info.seconds);
    return 0;
}

} // namespace gi::app
