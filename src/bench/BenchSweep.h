// The configurations `voxatlas bench` measures: direct light alone (the cost baseline, and
// 100 % indirect error by definition), then per GI mode not the cross product of every
// parameter (thousands of frames on llvmpipe) but a one-at-a-time sweep around the mode's
// base configuration (each row changes one setting) plus a few combined presets:
//   voxel: voxel.resolution, voxel.cascades, voxel.trace_scale, voxel.multiplier,
//          voxel.max_distance, and the other options (scene-centred cascade, the thesis'
//          mean coverage instead of the max-axis default, injection at 4v, the thesis'
//          fragment-mean injection);
//   atlas: atlas.resolution, atlas.samples, atlas.estimator, atlas.visibility, and
//          progressive accumulation over several frames (a separate plot series, since its
//          image needs N frames of a static scene).
// The base settings underneath are the program's defaults with the bench's fixed changes
// (material.specular=0, so images are comparable with the Lambertian reference; the thesis'
// allocation, render.plan=fixed, unless --set render.plan is given).
#pragma once

#include "render/FrameRenderer.h"
#include "core/Settings.h"

#include <optional>
#include <string>
#include <vector>

namespace gi::bench {

struct SettingChange {
    std::string key;     // a --set key, e.g. "voxel.resolution"
    std::string value;   // as on the command line, e.g. "64"
};

struct BenchConfiguration {
    render::GiMode mode = render::GiMode::Voxel;
    std::string label;                    // short name for tables and plot labels
    std::vector<SettingChange> changes;   // applied in order over the bench's base settings
    int accumulatedFrames = 1;            // frames rendered before the image is scored; > 1 only
                                          // for progressive atlas configurations
    bool base = false;                    // the mode's base configuration ("x base" ratios)
    double costEstimate = 1.0;            // relative run time, for the ETA only
};

enum class SweepSize {
    Smoke,   // a handful of cheap configurations, at least one per mode (the CI form)
    Quick,   // everything that fits the --quick time budget
    Full,    // adds the expensive atlas settings (2048^2 texels, 400 samples)
};

// "smoke", "quick", "full" (`voxatlas bench --sweep NAME`, the report's sweep line).
[[nodiscard]] const char* sweepSizeName(SweepSize size);
[[nodiscard]] std::optional<SweepSize> parseSweepSize(const std::string& name);

struct SweepOptions {
    SweepSize size = SweepSize::Full;
    float shortDistance = 1.0f;   // metres: the "short" voxel.max_distance for this scene
    int minProgressiveFrames = 1; // warm-up + timed frames: a progressive configuration
                                  // accumulates at least this many frames, so every timed
                                  // frame still gathers
};

[[nodiscard]] std::vector<BenchConfiguration> benchConfigurations(const SweepOptions& options);

// The plot series of a configuration: "direct", "voxel", "atlas", "atlas progressive" or
// "vpl".
[[nodiscard]] std::string seriesName(const BenchConfiguration& configuration);

// Every key that some configuration changes, in first-use order.
[[nodiscard]] std::vector<std::string> changedKeys(
        const std::vector<BenchConfiguration>& configurations);

// "key=value;key=value" of a configuration's changes (the CSV's `changed` column).
[[nodiscard]] std::string changesText(const BenchConfiguration& configuration);

// Applies a configuration's changes over `base`; false with the --set error on a bad change.
[[nodiscard]] bool applyConfiguration(const BenchConfiguration& configuration, Settings& settings,
        std::string& error);

// The voxel quality preset, under any plan: v=64, full-resolution trace, 37 cones moved in
// elevation by the dither, and on the adaptive plan one level of up to 256^3 injected at the
// plan's four light pixels per voxel (the accuracy suite's; the bench's "preset quality" row
// adds four levels of the fixed plan, which the one-level limit does not touch, injected at
// 4v).
[[nodiscard]] std::vector<SettingChange> voxelQualityPreset();

// The "short" voxel.max_distance for a scene: a quarter of its bounding-box diagonal, rounded
// to two significant digits (0.24 m for the Cornell box, 11 m for Sponza).
[[nodiscard]] float shortMaxDistance(float sceneDiagonal);

} // namespace gi::bench
