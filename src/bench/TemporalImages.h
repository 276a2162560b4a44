// Image grids for the temporal page: rows of equally sized panels, each row tone mapped at
// the auto exposure of its first panel with the filmic curve (or at a given exposure).
#pragma once

#include "core/Image.h"

#include <string>
#include <vector>

namespace gi::bench {

struct GridRow {
    std::vector<core::Image> panels;   // linear radiance, all of one size
    float exposure = 0.0f;             // 0: the auto exposure of the first panel
};

// The rows one under another, panels side by side, separated by thin grey gaps; the panels'
// exposure as each row says. Empty when there is nothing to show.
[[nodiscard]] core::Image composeGrid(const std::vector<GridRow>& rows);

// The auto exposure (core/ToneMap.h) of `image` over its non-black pixels.
[[nodiscard]] float autoExposureOf(const core::Image& image);

} // namespace gi::bench
