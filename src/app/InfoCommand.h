// `voxatlas info SCENE`: what a scene holds (counts, bounds, lights, cameras, materials)
// and the GPU memory its upload will take, without creating a GL context.
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

[[nodiscard]] int runInfo(const Config& config);

} // namespace gi::app
