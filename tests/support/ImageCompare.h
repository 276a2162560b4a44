// Golden-image comparison for GPU tests (Filament/VTK style). Images are compared in the
// encoding users see (8-bit sRGB) on three numbers: the largest per-channel difference,
// the fraction of pixels whose difference exceeds a threshold, and the mean difference.
// On failure the actual, expected and a diff image are written to <build>/test-output/.
// A missing baseline fails and writes the candidate; VOXATLAS_UPDATE_REFERENCES=1
// rewrites baselines deliberately.
#pragma once

#include "core/Image.h"

#include <string>

namespace gi::test {

struct ImageTolerance {
    // Largest per-channel difference (in 8-bit steps) a pixel may show before it counts as
    // failing: 6/255 absorbs rasterization-order and 8-bit rounding differences.
    int pixelThreshold = 6;
    // Fraction of pixels allowed over pixelThreshold: edges may shift by one pixel.
    double maxFailingFraction = 0.002;
    // Mean absolute difference over all channels, in 8-bit steps.
    double maxMeanAbsDiff = 0.5;
};

struct ImageDifference {
    int maxAbsDiff = 0;              // 8-bit steps, over all channels
    double failingFraction = 0.0;    // pixels with any channel over the threshold
    double meanAbsDiff = 0.0;        // 8-bit steps
    double rmse = 0.0;               // 8-bit steps
    bool sizeMismatch = false;
};

[[nodiscard]] ImageDifference compareImages(const core::Image& actual,
        const core::Image& expected, int pixelThreshold);

// Compares with tests/references/<name>.png (or an allowed alternate <name>_1.png).
// Returns an empty string on success, else a message with the three numbers and the files.
[[nodiscard]] std::string compareWithReference(const core::Image& actual,
        const std::string& name, const ImageTolerance& tolerance = {});

// Writes the actual image, the expected one and an amplified difference image to
// <build>/test-output/<name>.{actual,expected,diff}.png.
void writeDiagnostics(const std::string& name, const core::Image& actual,
        const core::Image* expected);

[[nodiscard]] std::string testOutputDir();

} // namespace gi::test
