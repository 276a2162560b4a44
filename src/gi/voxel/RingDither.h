// The cone ring's turn per pixel (voxel.jitter, cone_trace.frag): an ordered dither of 2x2 or
// 4x4 turns over square cells of trace pixels, whose turns the edge-aware filter (voxel.filter)
// averages back into a smooth result; none where the filter's window is too small for it.
#pragma once

namespace gi::voxel {

struct RingDither {
    int turns = 4;   // turns per axis: 4 (16 turns), 2 (4) or 1 (every pixel alike)
    int cell = 1;    // pixels per cell and axis, all turned alike

    // VoxelUniforms.smoothing.y (cone_trace.frag decodes it): 8 x turns + cell.
    [[nodiscard]] constexpr int code() const { return 8 * turns + cell; }
    bool operator==(const RingDither&) const = default;
};

// The dither for a filter of radius `filterTexels` trace texels, whose window is 2 r + 1 texels
// a side: cells of 2x2 pixels (a quad), and as many turns as the window holds whole periods
// of, at most 4x4. So every pixel's window averages every turn, and neighbours share their
// turn: the 4x2 pixels llvmpipe shades together hold 2 turns instead of 8 and walk more alike,
// and a group's loop runs until its longest walk ends (results-performance.md). 5x5 (half the
// resolution at the default radius): 2x2 turns of quads; 9x9 (full): 4x4 turns of quads. A 3x3
// window (a quarter) holds no period of quads, and the 2x2 turns of single pixels it held
// entered each window 4:2:2:1, not evenly: the quarter-resolution scoreboard was no better
// with them than without (results-performance.md), and the trace cost x1.2, so there every
// pixel turns alike, by the dither's mean turn (half the ring's spacing: a ring aligned with
// the surface's tangent axes scored worse). Without the filter (radius 0) the 4x4 dither of
// single pixels stays, as voxel.jitter asks for it.
constexpr RingDither ringDither(int filterTexels) {
    if (filterTexels <= 0) return {4, 1};
    const int window = 2 * filterTexels + 1;
    if (window < 4) return {1, 1};
    return {window >= 8 ? 4 : 2, 2};
}

} // namespace gi::voxel
