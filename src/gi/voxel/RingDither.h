// The cone ring's turn per pixel (voxel.jitter, cone_trace.frag): an ordered dither over a
// square of trace pixels, whose turns the edge-aware filter (voxel.filter) averages back into a
// smooth result.
#pragma once

namespace gi::voxel {

// The dither's period in trace pixels for a filter of radius `filterTexels` trace texels:
// 4 (16 turns), or 2 (4 turns) where the filter's window is 3x3 (a quarter of the resolution at
// the default radius). Such a window holds a 2x2 period whole at every pixel, and of a 4x4 one
// only 9 turns of 16; and neighbours whose rings differ by fewer turns walk more alike, which
// llvmpipe pays for by a group's longest walk (results-performance.md). Without the filter
// (radius 0) the 4x4 dither stays, as voxel.jitter asks for it.
constexpr int ringDitherPeriod(int filterTexels) {
    return filterTexels == 1 ? 2 : 4;
}

} // namespace gi::voxel
