// What the bench's two forms (the sweep and the accuracy suite) share: where Sponza is found,
// how reports name scene files, and the run's date and machine load.
#pragma once

#include "app/CommandLine.h"

#include <string>

namespace gi::app {

struct SceneChoice {
    std::string path;
    bool explicitPath = false;   // from --scene: a missing file is bad input, not a skip
};

// Sponza: $VOXATLAS_SPONZA, else the shared copy next to the source tree.
[[nodiscard]] std::string sponzaPath();

// The sweep's second scene: --scene, else sponzaPath().
[[nodiscard]] SceneChoice secondScene(const Config& config);

[[nodiscard]] bool isSponza(const std::string& path);

// The scene path as reports show it: relative to the source tree when it is inside it or next
// to it (assets/..., ../shared/...), so committed tables hold no machine-specific paths.
[[nodiscard]] std::string displayPath(const std::string& path);

// The first three fields of /proc/loadavg ("0.52 1.10 2.30"), or "" where there is none.
[[nodiscard]] std::string loadAverage();

// "YYYY-MM-DD HH:MM", local time.
[[nodiscard]] std::string localTime();

} // namespace gi::app
