// `voxatlas bench --suite quick|full`: the accuracy scoreboard. Loads each scene of the suite
// (bench/AccuracySuite.h) with its camera and lights, renders or loads its reference, scores
// every configuration with BenchRunner and writes the page (bench/AccuracyReport.h).
// `--scene a,b` limits the run to the named suite scenes. Targets missed are reported, not
// failed: the exit status says whether the scoreboard could be made (the CI thresholds live in
// tests/accuracy/).
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

// 0 success, 1 runtime failure, 2 bad usage or input.
[[nodiscard]] int runAccuracySuite(const Config& config);

} // namespace gi::app
