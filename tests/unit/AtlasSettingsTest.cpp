// The atlas.* keys: defaults (the thesis' 100 samples), word-valued settings that also take
// their numbers, and clean refusals.
#include "core/Settings.h"

#include <gtest/gtest.h>

namespace gi {
namespace {

TEST(AtlasSettings, DefaultsAndChoices) {
    Settings settings;
    EXPECT_EQ(settings.atlas.resolution, 1024);
    EXPECT_EQ(settings.atlas.samples, 100);
    EXPECT_EQ(settings.atlas.targetSamples, 1024);
    EXPECT_TRUE(settings.atlas.progressive);
    std::string error;
    ASSERT_TRUE(applySetting(settings, "atlas.estimator=merz2010", error)) << error;
    EXPECT_EQ(settings.atlas.estimator, 1);
    ASSERT_TRUE(applySetting(settings, "atlas.estimator=0", error)) << error;
    EXPECT_EQ(settings.atlas.estimator, 0);
    ASSERT_TRUE(applySetting(settings, "atlas.visibility=voxel", error)) << error;
    EXPECT_EQ(settings.atlas.visibility, 1);
    EXPECT_FALSE(applySetting(settings, "atlas.visibility=rays", error));
    EXPECT_NE(error.find("none|voxel"), std::string::npos) << error;
    EXPECT_EQ(settings.atlas.visibility, 1) << "a rejected value must not change the setting";
    EXPECT_FALSE(applySetting(settings, "atlas.gutter=1", error))
            << "gutters are at least 2 texels";
    EXPECT_FALSE(applySetting(settings, "atlas.resolution=8192", error));
    const std::string help = settingsHelp();
    EXPECT_NE(help.find("atlas.estimator        area"), std::string::npos) << help;
    EXPECT_NE(help.find("[area|merz2010]"), std::string::npos) << help;
}

} // namespace
} // namespace gi
