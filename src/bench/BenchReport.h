// What `voxatlas bench` writes: bench.csv (one row per measured configuration: every swept
// setting, frame and per-pass milliseconds, memory, errors against the reference and the
// reference's own noise), bench.md (a table per scene sorted by frame time with the Pareto
// frontier marked, and what each step along each frontier costs and buys), and pareto.png
// (drawn by scripts/plot_pareto.py from the CSV). A configuration is on its series' Pareto
// frontier when no other configuration of the same scene and series is at least as fast and
// at least as accurate (relative RMSE of the indirect component) and strictly better in one,
// and its indirect error is under 100 % (an all-zero indirect image, i.e. no GI, scores 100 %).
// Files are written under temporary names and renamed, so a failed run leaves no partial file.
#pragma once

#include "bench/BenchRunner.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gi::bench {

struct BenchSceneSummary {
    std::string name, path, cameraText;
    glm::ivec2 size{0};
    int referenceSpp = 0, referenceBounces = 0;
    double noiseIndirect = 0.0, noiseFinal = 0.0;   // ReferenceResult::noise
};

struct BenchRunInfo {
    std::string sweep;        // "quick", "full" or "smoke"
    std::string date;         // local time the run started
    std::string glRenderer;   // GL_RENDERER / GL_VERSION of the context
    std::string timing;       // how passes were timed
    int cores = 0;
    int warmupFrames = 0, timedFrames = 0, scoredFrames = 0;
    double seconds = 0.0;     // wall-clock duration of the run (references included)
    std::vector<BenchSceneSummary> scenes;
    std::vector<std::string> notes;   // e.g. a scene that was left out and why
    std::string loadBefore, loadAfter;   // /proc/loadavg at the start and the end (1, 5, 15 min)
};

// Marks the Pareto frontier of every (scene, series) and sets each frame ratio against the
// base configuration of the same scene and mode.
void finalizeMeasurements(std::vector<BenchMeasurement>& measurements);

// The CSV's columns, in order, for these measurements (tests check for them).
[[nodiscard]] std::vector<std::string> benchCsvColumns(
        const std::vector<BenchMeasurement>& measurements);
[[nodiscard]] std::string benchCsv(const std::vector<BenchMeasurement>& measurements);
[[nodiscard]] std::string benchMarkdown(const std::vector<BenchMeasurement>& measurements,
        const BenchRunInfo& info);

// Writes bench.csv and bench.md into `directory` (created if needed).
[[nodiscard]] bool writeBenchReport(const std::string& directory,
        const std::vector<BenchMeasurement>& measurements, const BenchRunInfo& info,
        std::string& error);

// Writes `text` to `path` through a temporary file renamed into place.
[[nodiscard]] bool writeFileAtomically(const std::filesystem::path& path, const std::string& text,
        std::string& error);

// Runs `python script csv png`; false with a one-line reason (no interpreter, a missing
// module, a failed run) when the plot was not written.
[[nodiscard]] bool runPlotScript(const std::string& python, const std::string& script,
        const std::string& csvPath, const std::string& pngPath, std::string& message);

} // namespace gi::bench
