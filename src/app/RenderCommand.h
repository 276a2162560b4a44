// `voxatlas render`: one headless frame to PNG, optional linear HDR and per-pass timings.
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

// Returns the process exit status: 0 success, 1 runtime failure, 2 bad usage or input.
[[nodiscard]] int runRender(const Config& config);

} // namespace gi::app
