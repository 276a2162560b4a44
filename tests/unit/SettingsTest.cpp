#include "core/Settings.h"

#include <gtest/gtest.h>

#include <set>

namespace gi {
namespace {

TEST(Settings, EveryKeyRoundTripsItsDefault) {
    std::set<std::string> keys;
    for (const SettingSpec& spec : settingSpecs()) {
        EXPECT_TRUE(keys.insert(spec.key).second) << "duplicate key " << spec.key;
        Settings settings;
        std::string error;
        EXPECT_TRUE(applySetting(settings, spec.key + "=" + spec.get(Settings{}), error)) << error;
        EXPECT_EQ(spec.get(settings), spec.get(Settings{})) << spec.key;
    }
}

TEST(Settings, AppliesAndValidates) {
    Settings settings;
    std::string error;
    EXPECT_TRUE(applySetting(settings, "render.supersample=3", error)) << error;
    EXPECT_EQ(settings.supersample, 3);
    EXPECT_FALSE(applySetting(settings, "render.supersample=5", error));
    EXPECT_NE(error.find("outside"), std::string::npos) << error;
    EXPECT_EQ(settings.supersample, 3) << "a rejected value must not change the setting";
    EXPECT_FALSE(applySetting(settings, "material.specular=abc", error));
    EXPECT_FALSE(applySetting(settings, "material.specular=inf", error));
    EXPECT_TRUE(applySetting(settings, "gl.debug=on", error));
    EXPECT_TRUE(settings.glDebug);
    EXPECT_FALSE(applySetting(settings, "gl.debug=maybe", error));
}

TEST(Settings, HelpListsEveryKey) {
    const std::string help = settingsHelp();
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.hidden) continue;
        EXPECT_NE(help.find(spec.key), std::string::npos) << spec.key;
    }
}

} // namespace
} // namespace gi
