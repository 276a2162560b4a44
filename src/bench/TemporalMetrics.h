// The flicker and ghosting figures of `voxatlas bench --temporal` (docs/results-temporal.md
// defines them). Everything is on Rec. 709 luminance Y of linear radiance, over pixels that
// show geometry (coverage above 0.5).
#pragma once

#include "core/Image.h"

#include <vector>

namespace gi::bench {

// One rendered frame of one radiance component and the geometry coverage of its pixels.
struct CoveredFrame {
    core::Image image;
    std::vector<float> coverage;   // one value in [0, 1] per pixel
};

// Mean relative frame-to-frame change between consecutive frames a and b:
//     sum_p |Y_b(p) - Y_a(p)| / sum_p (Y_a(p) + Y_b(p)) / 2
// over the pixels p covered in both, i.e. the mean absolute change divided by the mean value.
// 0 when no pixel is covered in both or both are black there.
[[nodiscard]] double relativeFrameChange(const CoveredFrame& a, const CoveredFrame& b);

// The mean of relativeFrameChange over consecutive pairs of `frames` (0 for fewer than two).
[[nodiscard]] double meanFrameChange(const std::vector<CoveredFrame>& frames);

// Mean luminance over the covered pixels of rows [firstRow, height): the floor of a view
// whose lower rows see only floor. 0 when none is covered.
[[nodiscard]] double meanLuminanceOfRows(const CoveredFrame& frame, int firstRow);

// Pixels where the light changed: covered in both, |Y_b - Y_a| > threshold.
[[nodiscard]] std::vector<bool> changedPixels(const CoveredFrame& a, const CoveredFrame& b,
        double threshold);

// The trail behind a moving object: mean of |Y_history - Y_fresh| over `region` (pixels that
// are also covered in `fresh`), divided by `floorLight`. 0 for an empty region.
[[nodiscard]] double trailBrightness(const CoveredFrame& history, const CoveredFrame& fresh,
        const std::vector<bool>& region, double floorLight);

// factor x factor pixel blocks averaged (image and coverage): the scale at which trails are
// measured, where a technique's per-pixel sample noise has averaged out but a trail has not.
[[nodiscard]] CoveredFrame blockMean(const CoveredFrame& frame, int factor);

// A false-colour image of |Y_a - Y_b| * gain (grey), for the strips.
[[nodiscard]] core::Image differenceImage(const core::Image& a, const core::Image& b, float gain);

} // namespace gi::bench
