// What `voxatlas bench --temporal` writes: results-temporal.md (the flicker figures of every
// path and configuration, the cascade snaps along the voxel runs, the moving cube's trail)
// and its pictures under images/: per path a grid of the indirect term (a row per
// configuration, the direct term on top; a column per strip frame), and for the moving cube
// the held frames, the fresh render and their difference. Each row shares one exposure (the
// auto exposure of its first frame) and the filmic curve, so changes along a row are real.
#pragma once

#include "bench/TemporalRuns.h"

#include <string>
#include <vector>

namespace gi::bench {

struct TemporalPathResult {
    TemporalPath path;
    std::vector<core::Image> directStrip;          // the direct term at stripFrames
    std::vector<FlickerMeasurement> measurements;  // one per configuration
};

struct TemporalRunInfo {
    std::string command;       // the command line that produced the page
    std::string form;          // "quick" or "full"
    std::string date, glRenderer;
    double seconds = 0.0;
    float blend = 0.0f;        // gi.temporal_blend of the filtered configurations
    float blendMoving = 0.0f;  // their gi.temporal_blend_moving
    std::vector<std::string> notes;   // e.g. Sponza left out and why
};

struct TemporalGhostResult {
    GhostSetup setup;
    std::vector<GhostMeasurement> measurements;
};

[[nodiscard]] std::string temporalMarkdown(const std::vector<TemporalPathResult>& paths,
        const TemporalGhostResult& ghost, const TemporalRunInfo& info);

// Writes `directory`/results-temporal.md and `directory`/images/temporal_*.png.
[[nodiscard]] bool writeTemporalReport(const std::string& directory,
        const std::vector<TemporalPathResult>& paths, const TemporalGhostResult& ghost,
        const TemporalRunInfo& info, std::string& error);

} // namespace gi::bench
