// The viewer's keys that step one voxel setting each (L, F1-F11): what a user tunes while
// watching the image. The viewer applies a step to a copy of its settings and keeps it only if
// the renderer accepts it.
#pragma once

#include "core/Settings.h"

#include <functional>
#include <vector>

namespace gi::app {

struct SettingHotkey {
    const char* key;       // GLFW-style name, as in `view --keys`
    const char* help;
    const char* setting;   // the settingSpecs() key whose new value the viewer announces
    // `coarsestReach`: distance (m) from the camera to the coarsest cascade level's far corner.
    std::function<void(Settings& settings, float coarsestReach)> step;
};

// In the order of the viewer's key help.
[[nodiscard]] const std::vector<SettingHotkey>& settingHotkeys();

} // namespace gi::app
