// `voxatlas bench --temporal [--quick]`: temporal stability (bench/TemporalRuns.h). Walks the
// camera down Sponza's atrium (10 cm per frame; left out with a note when Sponza is missing)
// and sideways through the Cornell box, in voxel and atlas mode with and without the temporal
// filter, and plays the animated Cornell box's cube against fresh renders; writes
// results-temporal.md and its pictures (bench/TemporalReport.h) to --out-dir (default docs).
// --quick is the CI form: the Cornell box alone, small images, few frames.
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

// 0 success, 1 runtime failure, 2 bad usage or input.
[[nodiscard]] int runTemporalBench(const Config& config);

} // namespace gi::app
