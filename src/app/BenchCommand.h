// `voxatlas bench`: picks the scenes (the Cornell box, and Sponza when it can be found), their
// cameras and image sizes, creates the headless context, and hands the sweep to src/bench/
// (BenchSweep, BenchRunner, BenchReport). `--sweep smoke` measures a handful of cheap
// configurations (one or two per mode) on the same scenes: the form CI runs.
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

// Returns the process exit status: 0 success, 1 runtime failure, 2 bad usage or input.
[[nodiscard]] int runBench(const Config& config);

} // namespace gi::app
