// Runs the bench's configurations on one scene and measures each (DESIGN.md "Measuring"):
//   time   warm-up frames, then the median of the timed frames: per pass (GpuProfiler medians;
//          glFinish wall clock on llvmpipe) and for the whole frame (wall clock from a glFinish
//          before render() to a glFinish after it);
//   memory FrameRenderer::memory(): bytes of every texture and buffer allocated, in total and
//          for the GI technique alone;
//   error  the final image of the last timed frames and as many more frames of the indirect
//          component (a progressive configuration: frames after it has accumulated all of its
//          sample sets), read back as linear radiance and scored against the ground-truth
//          renderer (cached on disk) over its geometry pixels with measureImageError: relative
//          RMSE of the indirect component and of the final image (root mean square over the
//          scored frames), and the indirect mean-energy ratio (mean over them).
// A mode the build cannot run (setMode fails) or a configuration it cannot honour is recorded
// as unavailable with the reason, and the sweep goes on.
#pragma once

#include "bench/BenchSweep.h"
#include "core/Image.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "reference/ReferenceRenderer.h"
#include "scene/CameraView.h"
#include "core/Settings.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace gi::bench {

struct BenchScene {
    std::string name;                  // short name for tables: "cornell_box", "Sponza"
    std::string path;                  // the glTF file
    std::string cameraText;            // how the camera was chosen ("camera 0", "0,2,14,...")
    const scene::Scene* scene = nullptr;
    scene::CameraView camera;
    glm::ivec2 size{0};                // output pixels
    std::vector<BenchConfiguration> configurations;
};

struct BenchMeasurement {
    std::string scene;
    BenchConfiguration configuration;
    glm::ivec2 size{0};
    bool available = true;
    std::string unavailableReason;     // why it was not measured
    std::map<std::string, std::string> settings;   // effective value of every swept key of
                                                   // this configuration's technique
    double frameMs = 0.0;              // median wall-clock ms of a whole timed frame
    double giMs = 0.0;                 // sum of the technique's pass medians (voxel/*, atlas/*)
    std::vector<gl::PassTiming> passes;   // per-pass medians over the timed frames
    std::size_t memoryBytes = 0;       // every GPU allocation of the renderer
    std::size_t giMemoryBytes = 0;     // the GI technique's allocations alone
    // Against the reference with measureImageError, over the scored frames: root mean square
    // of the per-frame relative RMSE, mean of the per-frame energy ratios.
    double relRmseIndirect = 0.0;      // indirect component
    double relRmseFinal = 0.0;         // final image
    double energyRatioIndirect = 0.0;  // sum ours / sum reference, indirect component
    int scoredFrames = 0;
    core::Image indirectImage;         // the last scored frame's indirect component
    double referenceNoiseIndirect = 0.0;   // ReferenceResult::noise of the reference used
    double referenceNoiseFinal = 0.0;
    int referenceSpp = 0;
    bool pareto = false;               // on its scene's and series' frontier (BenchReport)
    double frameRatio = 0.0;           // frameMs / the base configuration's (BenchReport)
    double directRatio = 0.0;          // frameMs / the direct-light-only frame's (BenchReport)
};

struct RunOptions {
    int warmupFrames = 2;
    int timedFrames = 3;
    int scoredFrames = 3;   // frames whose images are scored (the last timed ones for the final
                            // image; as many extra frames of the indirect component)
};

// One line per finished configuration: "[i/n]", the ETA and the measured numbers. The ETA
// sums the cost estimates of the configurations left, each at the seconds per cost unit
// measured so far for its scene and mode (else for its mode, else overall), so it corrects
// itself once a scene's first voxel or atlas configuration has run.
class BenchProgress {
public:
    struct PlannedRun {
        std::string scene;
        render::GiMode mode = render::GiMode::Voxel;
        double cost = 1.0;   // BenchConfiguration::costEstimate
    };
    BenchProgress(std::vector<PlannedRun> plan, std::FILE* out);
    // Call once per configuration, in plan order.
    void report(const BenchMeasurement& m);

private:
    double secondsPerCost(const PlannedRun& run) const;

    std::vector<PlannedRun> mPlan;
    std::size_t mDone = 0;
    std::FILE* mOut;
    std::chrono::steady_clock::time_point mLast;
    std::map<std::pair<std::string, render::GiMode>, std::pair<double, double>> mSpent;   // s, cost
};

class BenchRunner {
public:
    BenchRunner(const Settings& base, RunOptions options);

    // Renders (or loads from the disk cache) the ground truth of `scene`. Empty on failure.
    [[nodiscard]] reference::ReferenceResult reference(const BenchScene& scene,
            std::string& error) const;

    // Measures every configuration of `scene` with a current GL context. False only when the
    // renderer cannot be set up at all (`error`); unavailable configurations are results.
    [[nodiscard]] bool run(const BenchScene& scene, const reference::ReferenceResult& reference,
            BenchProgress& progress, std::vector<BenchMeasurement>& results,
            std::string& error) const;

private:
    Settings mBase;
    RunOptions mOptions;
};

} // namespace gi::bench
