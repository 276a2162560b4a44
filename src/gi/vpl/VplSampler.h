// Draws VPLs from the lit texels of the reflective shadow maps in proportion to their flux.
// The draw runs on the CPU over a readback: it happens only when lights or geometry change,
// the texels number some 10^5, and a CPU draw is deterministic and simple (a GPU prefix sum
// would pay off only if the VPLs were redrawn every frame).
#pragma once

#include "gi/vpl/RsmTexel.h"
#include "gl/Shared.h"

#include <vector>

namespace gi::vpl {

// `count` VPLs by systematic resampling along the texels' cumulative flux (r + g + b): texel j
// of weight w_j is drawn about count * w_j / W times, each copy carrying flux_j * W / (count
// w_j) in flux.rgb and the surface it stands for, area_j * W / (count w_j), in flux.w (the
// gather's clamp follows it), so the VPLs' flux sums to the texels' (exactly, up to rounding,
// in the summed channel).
// Consecutive VPLs come from neighbouring texels, so VPLs i, i + 16, i + 32, ... (one
// interleaved subset) spread over every light and surface. Empty when no texel is lit.
[[nodiscard]] std::vector<shader::GpuVpl> drawVpls(const std::vector<RsmTexel>& texels, int count);

// The same, drawing texel j in proportion to its flux (r + g + b) x importance[j] (vpl.importance,
// VplImportance.h); each copy carries flux_j x W / (count x weight_j), so every texel's expected
// flux is still its own.
[[nodiscard]] std::vector<shader::GpuVpl> drawVpls(const std::vector<RsmTexel>& texels,
        const std::vector<float>& importance, int count);

} // namespace gi::vpl
