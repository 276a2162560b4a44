#include "core/Settings.h"

#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>

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

// A valid value of `spec` other than its default: the first candidate its setter accepts that
// reads back different. Covers ints, floats, booleans and word choices (which accept numbers).
std::optional<std::string> nonDefaultValue(const SettingSpec& spec) {
    static const char* const kCandidates[] = {"1", "2", "0", "3", "0.5", "0.25", "5", "7", "17",
            "64", "100", "512", "3000", "2.5"};
    const std::string defaultValue = spec.get(Settings{});
    for (const char* candidate : kCandidates) {
        Settings settings;
        std::string error;
        if (spec.set(settings, candidate, error) && spec.get(settings) != defaultValue) {
            return candidate;
        }
    }
    return std::nullopt;
}

// The group a key belongs to by its prefix, as a Settings sub-struct (or none).
bool sectionEquals(const std::string& section, const Settings& a, const Settings& b) {
    if (section == "shadow") return a.shadow == b.shadow;
    if (section == "voxel") return a.voxel == b.voxel;
    if (section == "atlas") return a.atlas == b.atlas;
    if (section == "reference") return a.reference == b.reference;
    if (section == "linespace") return a.lineSpace == b.lineSpace;
    return true;
}

// Setting one key changes what that key reads and nothing else: two keys wired to one field,
// or a key writing another key's field, fail here (a default round trip cannot see either).
TEST(Settings, EachKeyChangesOnlyItself) {
    const Settings defaults;
    for (const SettingSpec& spec : settingSpecs()) {
        const std::optional<std::string> value = nonDefaultValue(spec);
        ASSERT_TRUE(value) << spec.key << ": no candidate value differs from the default";
        Settings settings;
        std::string error;
        ASSERT_TRUE(applySetting(settings, spec.key + "=" + *value, error)) << error;
        EXPECT_NE(spec.get(settings), spec.get(defaults)) << spec.key << "=" << *value;
        for (const SettingSpec& other : settingSpecs()) {
            if (other.key == spec.key) continue;
            EXPECT_EQ(other.get(settings), other.get(defaults))
                    << "setting " << spec.key << "=" << *value << " changed " << other.key;
        }
        const std::string section = spec.key.substr(0, spec.key.find('.'));
        for (const char* group : {"shadow", "voxel", "atlas", "reference", "linespace"}) {
            EXPECT_EQ(sectionEquals(group, settings, defaults), group != section)
                    << spec.key << " and the " << group << " settings";
        }
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
    EXPECT_TRUE(applySetting(settings, "voxel.occupancy_resolution=64", error)) << error;
    EXPECT_EQ(settings.voxel.occupancyResolution, 64);
    EXPECT_FALSE(applySetting(settings, "voxel.occupancy_resolution=48", error));
    EXPECT_NE(error.find("power of two"), std::string::npos) << error;
    EXPECT_FALSE(applySetting(settings, "voxel.occupancy_resolution=2", error));
    EXPECT_EQ(settings.voxel.occupancyResolution, 64) << "a rejected value must not change it";
    EXPECT_TRUE(applySetting(settings, "voxel.occupancy_resolution=0", error)) << error;
    // Nested cascade levels share 2x2x2 voxel blocks, octree levels halve: refused in any mode.
    EXPECT_FALSE(applySetting(settings, "voxel.resolution=48", error));
    EXPECT_NE(error.find("power of two"), std::string::npos) << error;
    EXPECT_FALSE(applySetting(settings, "voxel.resolution=0", error));
    EXPECT_TRUE(applySetting(settings, "voxel.resolution=64", error)) << error;
    EXPECT_FALSE(applySetting(settings, "vpl.svo_resolution=100", error));
    EXPECT_TRUE(applySetting(settings, "vpl.svo_resolution=256", error)) << error;
    // Voxelization samples a pixel: a power of two up to 8, or 0 for the plan's.
    EXPECT_FALSE(applySetting(settings, "voxel.msaa=3", error));
    EXPECT_NE(error.find("power of two"), std::string::npos) << error;
    EXPECT_FALSE(applySetting(settings, "voxel.msaa=16", error));
    EXPECT_TRUE(applySetting(settings, "voxel.msaa=2", error)) << error;
    EXPECT_EQ(settings.voxel.msaa, 2);
    EXPECT_TRUE(applySetting(settings, "voxel.msaa=0", error)) << error;
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
