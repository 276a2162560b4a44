// render.plan as the command line settles it (app/PlanChoice.h): adaptive by default; a key the
// adaptive plan sizes selects the fixed plan, with a note naming render.plan=fixed; that key
// together with render.plan=adaptive is refused; render.plan=fixed takes any of them quietly.
#include "app/PlanChoice.h"

#include <gtest/gtest.h>

namespace gi::app {
namespace {

struct Chosen {
    bool ok = false;
    Settings settings;
    PlanChoice choice;
    std::string error;
};

// `assignments` as --set would apply them, in order.
Chosen choose(const std::vector<std::string>& assignments) {
    Chosen c;
    std::vector<std::string> keys;
    for (const std::string& assignment : assignments) {
        EXPECT_TRUE(applySetting(c.settings, assignment, c.error)) << c.error;
        keys.push_back(assignment.substr(0, assignment.find('=')));
    }
    c.ok = choosePlan(c.settings, keys, c.choice, c.error);
    return c;
}

TEST(PlanChoice, AdaptiveByDefault) {
    const Chosen c = choose({"voxel.resolution=64", "atlas.samples=16"});
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_EQ(c.settings.plan, PLAN_ADAPTIVE);
    EXPECT_TRUE(c.choice.note.empty());
    EXPECT_NE(c.choice.why.find("the default"), std::string::npos) << c.choice.why;
}

TEST(PlanChoice, AKeyTheAdaptivePlanSizesSelectsFixed) {
    const Chosen c = choose({"voxel.cascades=4", "atlas.resolution=512", "voxel.cascades=5"});
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_EQ(c.settings.plan, PLAN_FIXED);
    EXPECT_EQ(c.settings.voxel.levels, 5);
    EXPECT_EQ(c.settings.atlas.resolution, 512);
    EXPECT_NE(c.choice.note.find("voxel.cascades and atlas.resolution set, so render.plan=fixed"),
            std::string::npos) << c.choice.note;
    EXPECT_NE(c.choice.why.find("voxel.cascades and atlas.resolution"), std::string::npos);
}

TEST(PlanChoice, AnExplicitPlanDecides) {
    const Chosen fixed = choose({"voxel.extent=2", "render.plan=fixed"});
    ASSERT_TRUE(fixed.ok) << fixed.error;
    EXPECT_EQ(fixed.settings.plan, PLAN_FIXED);
    EXPECT_TRUE(fixed.choice.note.empty()) << "asked for: nothing to point out";
    EXPECT_EQ(fixed.choice.why, "render.plan=fixed was set");
    const Chosen adaptive = choose({"render.plan=adaptive", "voxel.size=0.1"});
    ASSERT_TRUE(adaptive.ok) << adaptive.error;
    EXPECT_EQ(adaptive.settings.plan, PLAN_ADAPTIVE);
}

TEST(PlanChoice, AdaptiveWithAKeyItSizesIsRefused) {
    const Chosen c = choose({"voxel.scene_centred=1", "render.plan=adaptive"});
    EXPECT_FALSE(c.ok);
    EXPECT_NE(c.error.find("--set voxel.scene_centred: render.plan=adaptive sizes it"),
            std::string::npos) << c.error;
    EXPECT_NE(c.error.find("render.plan=fixed"), std::string::npos) << c.error;
}

TEST(PlanChoice, ViewerStepsFromWhatTheAdaptivePlanShows) {
    Settings requested;
    Settings effective = requested;
    effective.voxel.levels = 1;
    effective.voxel.sceneCentred = true;
    const Settings cascades = settingsToStep(requested, effective, "voxel.cascades");
    EXPECT_EQ(cascades.plan, PLAN_FIXED);
    EXPECT_EQ(cascades.voxel.levels, 1);
    EXPECT_TRUE(cascades.voxel.sceneCentred);
    const Settings resolution = settingsToStep(requested, effective, "voxel.resolution");
    EXPECT_EQ(resolution.plan, PLAN_ADAPTIVE);
    EXPECT_EQ(resolution.voxel.levels, requested.voxel.levels);
}

} // namespace
} // namespace gi::app
