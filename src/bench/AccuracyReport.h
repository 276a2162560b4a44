// What `voxatlas bench --suite` writes into its output directory:
//   results-accuracy.md      scene x configuration: relative RMSE of the indirect component,
//                            its energy ratio, the final image's error over the no-GI
//                            baseline's, the thin-wall leak, and every target met or missed;
//   accuracy.csv             the same numbers, one row per scene and configuration (the CI
//                            thresholds read it);
//   images/accuracy_*.png    per scene: reference | voxel | atlas | their error maps.
// Scores (all over the reference's geometry pixels, reference::measureImageError):
//   final ratio to no GI   relRmseFinal / relRmseFinal of the direct-only image: below 1, the
//                          GI brings the image closer to the truth than leaving it out does;
//   leak                   mean indirect luminance of the dark room's view over the lit
//                          room's, per configuration (the reference's own is shown beside it);
//   noise-limited          the reference's Monte Carlo noise is above a fifth of the error it
//                          measures, so the score says little (marked, never hidden).
#pragma once

#include "bench/AccuracySuite.h"
#include "bench/BenchRunner.h"

#include <optional>
#include <string>
#include <vector>

namespace gi::bench {

struct SuiteSceneResult {
    SuiteScene scene;
    glm::ivec2 size{0};
    reference::ReferenceResult reference;
    std::vector<BenchMeasurement> measurements;   // in suiteConfigurations() order
};

struct SuiteScore {
    std::string scene, configuration;
    SceneKind kind = SceneKind::Scored;
    bool available = true;
    std::string unavailableReason;
    double relRmseIndirect = 0.0, energyIndirect = 0.0, relRmseFinal = 0.0;
    double finalRatioToNoGi = 0.0;    // NaN without a direct-mode row
    double indirectRatioToNoGi = 0.0; // relRmseIndirect / the direct mode's; NaN without it
    // relRmseIndirect x the reference's RMS over its mean: the RMSE over the reference's mean
    // radiance, the normalisation the accuracy issue's figures fit (its no-GI baselines are
    // above 1: an image of zeros scores the reference's RMS / mean).
    double relRmseIndirectPerMean = 0.0;
    std::vector<std::string> missesPerMean;   // the targets missed with that normalisation
    double meanIndirect = 0.0;        // mean indirect luminance over geometry pixels
    std::optional<double> leak;       // the dark room's rows only
    bool noiseLimited = false;
    SuiteTarget target;
    std::vector<std::string> misses;  // each target missed, e.g. "energy 0.71 < 0.9"
    double frameMs = 0.0;
};

// The root mean square of `image`'s channels over their mean, over the pixels whose coverage
// exceeds kGeometryCoverage (the sums of reference::measureImageError); NaN without any.
[[nodiscard]] double rmsOverMean(const core::Image& image, const std::vector<float>& coverage);

// The mean luminance of `image` over the pixels whose coverage exceeds kGeometryCoverage.
[[nodiscard]] double meanGeometryLuminance(const core::Image& image,
        const std::vector<float>& coverage);

[[nodiscard]] std::vector<SuiteScore> scoreSuite(const std::vector<SuiteSceneResult>& results);

struct SuiteRunInfo {
    std::string size;          // "quick" / "full"
    std::string command;       // how to reproduce the page
    std::string date, glRenderer, loadBefore, loadAfter;
    double seconds = 0.0;
    bool glossy = false;       // glTF's BRDF on the GPU and in the path tracer, else Lambert
    std::vector<std::string> notes;   // scenes left out and why
};

[[nodiscard]] std::string accuracyCsv(const std::vector<SuiteScore>& scores);
[[nodiscard]] std::string accuracyMarkdown(const std::vector<SuiteSceneResult>& results,
        const std::vector<SuiteScore>& scores, const SuiteRunInfo& info);

// Writes results-accuracy.md, accuracy.csv and images/accuracy_<scene>.png into `directory`.
[[nodiscard]] bool writeAccuracyReport(const std::string& directory,
        const std::vector<SuiteSceneResult>& results, const SuiteRunInfo& info,
        std::string& error);

} // namespace gi::bench
