// Which resource plan (render.plan) a run uses, and why. The adaptive plan is the default and
// sizes the keys of render::adaptivePlanKeys() (voxel.cascades, voxel.extent, ...) from the
// scene. Whoever sets one of those keys wants that value, so a value given for one
//   - without render.plan selects render.plan=fixed, with a one-line note that says so;
//   - with render.plan=adaptive is refused (the plan would replace it without a word);
//   - with render.plan=fixed is simply used.
#pragma once

#include "core/Settings.h"

#include <string>
#include <vector>

namespace gi::app {

struct PlanChoice {
    bool planGiven = false;   // --set render.plan=... was on the command line
    std::string why;          // follows the plan's name in `voxatlas info`
    std::string note;         // for stderr when a key selected the fixed plan, else empty
};

// Settles settings.plan from the keys --set gave (in order); false with `error` on a conflict.
[[nodiscard]] bool choosePlan(Settings& settings, const std::vector<std::string>& keysGiven,
        PlanChoice& choice, std::string& error);

// What a viewer key that steps `key` starts from: `requested`, or, for a key the adaptive plan
// sizes, the values in effect under render.plan=fixed, so the step changes what is on screen
// (one cascade level more than the plan shows, not than the unused request).
[[nodiscard]] Settings settingsToStep(const Settings& requested, const Settings& effective,
        const std::string& key);

} // namespace gi::app
