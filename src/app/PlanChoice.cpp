#include "app/PlanChoice.h"

#include "render/ResourcePlan.h"

#include <algorithm>

namespace gi::app {
namespace {

bool sizedByAdaptivePlan(const std::string& key) {
    const std::vector<std::string>& keys = render::adaptivePlanKeys();
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
    }
    return text;
}

} // namespace

bool choosePlan(Settings& settings, const std::vector<std::string>& keysGiven, PlanChoice& choice,
        std::string& error) {
    choice = {};
    std::vector<std::string> sized;
    for (const std::string& key : keysGiven) {
        if (key == "render.plan") choice.planGiven = true;
        if (sizedByAdaptivePlan(key) && std::find(sized.begin(), sized.end(), key) == sized.end()) {
            sized.push_back(key);
        }
    }
    const std::string given = joined(sized);
    if (choice.planGiven) {
        if (settings.plan == PLAN_ADAPTIVE && !sized.empty()) {
            error = "--set " + given + ": render.plan=adaptive sizes " +
                    (sized.size() == 1 ? "it" : "them") +
                    " from the scene; set render.plan=fixed to choose " +
                    (sized.size() == 1 ? "it" : "them") +
                    ", or steer the adaptive plan with voxel.size and atlas.texel_size";
            return false;
        }
        choice.why = std::string("render.plan=") +
                     (settings.plan == PLAN_ADAPTIVE ? "adaptive" : "fixed") + " was set";
        return true;
    }
    if (sized.empty()) {
        choice.why = "the default (render.plan=fixed gives the thesis' allocation)";
        return true;
    }
    settings.plan = PLAN_FIXED;
    choice.why = given + " set, which the adaptive plan would size";
    choice.note = given + " set, so render.plan=fixed (the adaptive default sizes " +
                  joined(render::adaptivePlanKeys()) +
                  " from the scene); --set render.plan=fixed says so explicitly";
    return true;
}

Settings settingsToStep(const Settings& requested, const Settings& effective,
        const std::string& key) {
    if (requested.plan != PLAN_ADAPTIVE || !sizedByAdaptivePlan(key)) return requested;
    Settings fixed = effective;
    fixed.plan = PLAN_FIXED;
    return fixed;
}

} // namespace gi::app
