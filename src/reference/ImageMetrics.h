// Error of an image against a ground-truth image, on linear radiance (DESIGN.md "Measuring"):
// how far the voxel and atlas GI modes are from the reference renderer. With a = the image
// under test, b = the reference, sums over the counted pixels p and channels c in {R, G, B}:
//   relative RMSE      sqrt( sum (a - b)^2 / sum b^2 )   (scale-free; 0.01 = 1 %)
//   mean-energy ratio  sum a / sum b                     (1 = same total energy; > 1 brighter)
//   RMSE               sqrt( sum (a - b)^2 / (3 n) )     (n counted pixels; radiance units)
//   max abs            max |a - b|                       (radiance units)
// Counted pixels are the "geometry pixels": those whose mask value (normally the reference's
// coverage, ReferenceResult::coverage) exceeds a threshold, so background and silhouette
// pixels, which a rasterizer and a path tracer cover differently, do not dominate the score.
#pragma once

#include "core/Image.h"

#include <cstddef>
#include <span>

namespace gi::reference {

// Pixels whose coverage exceeds this are "geometry pixels": every path of the pixel hit a
// surface (up to float rounding of the covered fraction).
constexpr float kGeometryCoverage = 0.999f;

struct ImageErrors {
    double relativeRmse = 0.0;   // 0 when both images are zero over the counted pixels
    double energyRatio = 1.0;    // 1 when both sums are zero; +inf when only the reference's is
    double rmse = 0.0;
    double maxAbs = 0.0;
    std::size_t pixels = 0;      // counted pixels
    bool sizeMismatch = false;   // then nothing is counted and the numbers are NaN
};

// Compares `actual` with `reference` over the pixels where mask[p] > threshold (mask:
// width * height values, rows top to bottom), or over all pixels when the mask is empty.
// A mask of the wrong size counts as a size mismatch. With no counted pixels the ratios are
// NaN. Non-finite pixel values make the results NaN or infinite, never silently finite.
[[nodiscard]] ImageErrors measureImageError(const core::Image& actual,
        const core::Image& reference, std::span<const float> mask = {},
        float threshold = kGeometryCoverage);

} // namespace gi::reference
