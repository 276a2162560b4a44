// The renders behind `voxatlas bench --temporal`: a camera path through a static scene, one
// renderer per configuration rendering every frame in order (so caches and the temporal
// filter's history persist as in the viewer), and the animated Cornell box's moving cube
// against fresh renders of the same pose. The figures come from bench/TemporalMetrics.h.
#pragma once

#include "bench/TemporalMetrics.h"
#include "core/Settings.h"
#include "gl/ShaderLibrary.h"
#include "render/OutputCatalog.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi::bench {

// A straight camera path: `frames` frames, the eye moving by `step` every frame.
struct TemporalPath {
    std::string name;                  // "sponza_walk"
    std::string description;           // how the report describes it
    std::string scenePath;             // as the report shows it
    const scene::Scene* scene = nullptr;
    scene::CameraView start;
    glm::vec3 step{0.0f};              // metres per frame
    int frames = 0;
    // Frames rendered at the start before the path, so progressive methods start converged
    // (as a viewer's user starts walking from a settled view) and convergence is not flicker.
    int warmupFrames = 0;
    glm::ivec2 size{0};
};

// What one renderer is set to for a run.
struct TemporalConfiguration {
    std::string label;                 // "voxel + filter"
    render::GiMode mode = render::GiMode::Voxel;
    Settings settings;
};

struct FlickerMeasurement {
    std::string path, label;
    double indirectChange = 0.0;       // meanFrameChange of the indirect term
    double directChange = 0.0;         // the same of the exact direct term along the path
    std::vector<double> perFrame;      // relativeFrameChange of the indirect term into frame i
    // Whether the technique placed its light anew at frame i (GiOutputs::resampled: the
    // voxel cascade snapped to the camera).
    std::vector<bool> cascadeMoved;
    std::vector<core::Image> strip;    // the indirect term at stripFrames(path)
    double seconds = 0.0;
};

// Frames the report shows of a path: first, two between, last.
[[nodiscard]] std::vector<int> stripFrames(int frames);

// The direct term (mode direct, --output direct) of every frame of `path`.
[[nodiscard]] bool renderDirectPath(const TemporalPath& path, const Settings& settings,
        gl::ShaderLibrary& shaders, std::vector<CoveredFrame>& frames, std::string& error);

// The indirect term of every frame under `configuration`, scored against `direct`.
[[nodiscard]] bool measureFlicker(const TemporalPath& path,
        const TemporalConfiguration& configuration, const std::vector<CoveredFrame>& direct,
        gl::ShaderLibrary& shaders, FlickerMeasurement& result, std::string& error);

// The animated scene: settled at startTime, then the animation played for movingFrames frames
// of stepSeconds each, then held still for holdFrames frames.
struct GhostSetup {
    scene::Scene* scene = nullptr;     // posed here (scene/Animation.h)
    std::string scenePath;
    scene::CameraView camera;
    glm::ivec2 size{0};
    float startTime = 0.0f;            // s
    float stepSeconds = 0.0f;
    int settleFrames = 0;              // before the motion, and of every fresh render
    int movingFrames = 0;
    int holdFrames = 4;
    float floorRows = 0.8f;            // rows below this fraction of the height see the floor
    float regionThreshold = 0.05f;     // the motion region: change above this x floor light
    int block = 4;                     // trails are measured on block x block pixel means
};

struct GhostMeasurement {
    std::string label;
    double floorLight = 0.0;           // mean indirect luminance of the floor, fresh, last pose
    double regionFraction = 0.0;       // share of the covered pixels in the motion region
    std::vector<double> trail;         // trailBrightness after each held frame 1..holdFrames
    double trailMoving = 0.0;          // the same on the last moving frame
    std::vector<core::Image> strip;    // held frames, the fresh render, |difference| x 10
};

[[nodiscard]] bool measureGhosting(const GhostSetup& setup,
        const TemporalConfiguration& configuration, gl::ShaderLibrary& shaders,
        GhostMeasurement& result, std::string& error);

} // namespace gi::bench
