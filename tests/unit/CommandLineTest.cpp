#include "app/CommandLine.h"

#include <gtest/gtest.h>

#include <iterator>
#include <utility>
#include <vector>

namespace gi::app {
namespace {

std::optional<Config> parse(std::vector<const char*> args, std::string& error) {
    args.insert(args.begin(), "voxatlas");
    return parseCommandLine(int(args.size()), args.data(), error);
}

TEST(CommandLine, DefaultsToViewOfTheCornellBox) {
    std::string error;
    const auto config = parse({}, error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->command, Command::View);
    EXPECT_NE(config->scenePath.find("cornell_box.gltf"), std::string::npos);
}

TEST(CommandLine, ParsesRender) {
    std::string error;
    const auto config = parse({"render", "s.gltf", "--out", "a.png", "--hdr", "a.exr", "--mode",
                                      "voxel", "--output", "indirect", "--width", "320", "--height",
                                      "200", "--camera", "1", "--gl", "osmesa", "--set",
                                      "material.specular=0", "--timings", "t.json"},
            error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->command, Command::Render);
    EXPECT_EQ(config->scenePath, "s.gltf");
    EXPECT_EQ(config->mode, render::GiMode::Voxel);
    EXPECT_EQ(config->output, render::OutputComponent::Indirect);
    EXPECT_EQ(config->width, 320);
    EXPECT_EQ(config->height, 200);
    EXPECT_EQ(config->cameraIndex, 1);
    EXPECT_EQ(config->gl, platform::HeadlessProvider::OSMesa);
    EXPECT_TRUE(config->glExplicit);
    EXPECT_EQ(config->settings.specular, 0.0f);
    EXPECT_EQ(config->timingsPath, "t.json");
}

TEST(CommandLine, ParsesEveryMode) {
    const std::pair<const char*, render::GiMode> modes[] = {{"direct", render::GiMode::Direct},
            {"voxel", render::GiMode::Voxel}, {"atlas", render::GiMode::Atlas},
            {"vpl", render::GiMode::Vpl}, {"reference", render::GiMode::Reference}};
    ASSERT_EQ(std::size(modes), render::modeCatalog().size());
    for (const auto& [name, mode] : modes) {
        std::string error;
        const auto config = parse({"render", "s.gltf", "--out", "a.png", "--mode", name}, error);
        ASSERT_TRUE(config) << name << ": " << error;
        EXPECT_EQ(config->mode, mode) << name;
    }
    std::string error;
    const auto defaults = parse({"render", "s.gltf", "--out", "a.png"}, error);
    ASSERT_TRUE(defaults) << error;
    EXPECT_EQ(defaults->mode, render::GiMode::Direct) << "--mode defaults to direct";
}

TEST(CommandLine, ParsesCameraSpecAndLights) {
    std::string error;
    const auto config = parse({"render", "s.gltf", "--out", "a.png", "--camera",
                                      "0,1,2,0,1,0,45", "--light", "point:0,1,0:1,1,1:2.5",
                                      "--light", "dir:0,-1,0:1,0.5,0.25:3", "--light",
                                      "spot:0,2,0:0,-1,0:1,1,1:10:10,30"},
            error);
    ASSERT_TRUE(config) << error;
    ASSERT_TRUE(config->cameraSpec);
    EXPECT_EQ(config->cameraSpec->eye, glm::vec3(0, 1, 2));
    EXPECT_EQ(config->cameraSpec->yfovDegrees, 45.0f);
    ASSERT_EQ(config->extraLights.size(), 3u);
    EXPECT_EQ(config->extraLights[0].type, scene::LightType::Point);
    EXPECT_EQ(config->extraLights[0].intensity, 2.5f);
    EXPECT_EQ(config->extraLights[1].type, scene::LightType::Directional);
    EXPECT_EQ(config->extraLights[1].direction, glm::vec3(0, -1, 0));
    EXPECT_EQ(config->extraLights[2].type, scene::LightType::Spot);
    EXPECT_NEAR(config->extraLights[2].outerConeAngle, glm::radians(30.0f), 1e-6f);
}

TEST(CommandLine, ParsesSkyAndRectLights) {
    std::string error;
    const auto config = parse({"render", "s.gltf", "--out", "a.png", "--light",
                                      "sky:0.5,0.75,1:2", "--light",
                                      "rect:1,2,3:0.4,0,0:0,0,-0.2:1,0.5,0.25:8"},
            error);
    ASSERT_TRUE(config) << error;
    ASSERT_EQ(config->extraLights.size(), 2u);
    const scene::Light& sky = config->extraLights[0];
    EXPECT_EQ(sky.type, scene::LightType::Sky);
    EXPECT_EQ(sky.color * sky.intensity, glm::vec3(1.0f, 1.5f, 2.0f)) << "radiance";
    const scene::Light& rect = config->extraLights[1];
    EXPECT_EQ(rect.type, scene::LightType::Area);
    EXPECT_EQ(rect.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(rect.direction, glm::vec3(0, 1, 0)) << "cross(u, v) faces +y";
    ASSERT_EQ(rect.emitters.size(), 2u);
    float area = 0.0f;
    glm::vec3 lowest(1e9f), highest(-1e9f);
    for (const scene::EmitterTriangle& t : rect.emitters) {
        area += t.area();
        EXPECT_NEAR(glm::dot(t.normal(), glm::vec3(0, 1, 0)), 1.0f, 1e-6f) << "front side up";
        EXPECT_EQ(t.radiance, glm::vec3(8.0f, 4.0f, 2.0f));
        EXPECT_FALSE(t.twoSided);
        EXPECT_EQ(t.instance, -1) << "not scene geometry";
        for (const glm::vec3& p : {t.p0, t.p1, t.p2}) {
            lowest = glm::min(lowest, p);
            highest = glm::max(highest, p);
        }
    }
    EXPECT_NEAR(area, 0.08f, 1e-6f);
    EXPECT_EQ(lowest, glm::vec3(0.8f, 2.0f, 2.9f));
    EXPECT_EQ(highest, glm::vec3(1.2f, 2.0f, 3.1f));
}

TEST(CommandLine, ParsesViewScripting) {
    std::string error;
    const auto config = parse({"view", "--frames", "5", "--screenshot", "s.png", "--keys", "2:G,4:F12"},
            error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->frames, 5);
    ASSERT_EQ(config->keys.size(), 2u);
    EXPECT_EQ(config->keys[1].frame, 4);
    EXPECT_EQ(config->keys[1].key, "F12");
}

TEST(CommandLine, ParsesViewMotionAndDrops) {
    std::string error;
    const auto config = parse({"view", "--move", "0.5,0,0", "--move-frames", "20", "--drop",
            "3:a:b.gltf", "--drop", "7:c.glb", "--hdr", "v.pfm"}, error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->cameraMove, glm::vec3(0.5f, 0.0f, 0.0f));
    EXPECT_EQ(config->moveFrames, 20);
    ASSERT_EQ(config->drops.size(), 2u);
    EXPECT_EQ(config->drops[0].frame, 3);
    EXPECT_EQ(config->drops[0].path, "a:b.gltf");
    EXPECT_EQ(config->drops[1].path, "c.glb");
    EXPECT_EQ(config->hdrPath, "v.pfm");
}

TEST(CommandLine, ViewOpensInVoxelModeUnlessAsked) {
    std::string error;
    const auto view = parse({"view"}, error);
    ASSERT_TRUE(view) << error;
    EXPECT_EQ(view->mode, render::GiMode::Voxel);
    const auto direct = parse({"view", "--mode", "direct"}, error);
    ASSERT_TRUE(direct) << error;
    EXPECT_EQ(direct->mode, render::GiMode::Direct);
}

TEST(CommandLine, ViewStartsInTheModeAsked) {
    std::string error;
    const auto config = parse({"view", "--mode", "voxel"}, error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->mode, render::GiMode::Voxel);
    const auto bench = parse({"bench", "--sweep", "smoke"}, error);
    ASSERT_TRUE(bench) << error;
    EXPECT_EQ(bench->sweep, bench::SweepSize::Smoke);
}

struct Rejection {
    std::vector<const char*> args;
    const char* mentions;
};

class CommandLineRejects : public ::testing::TestWithParam<Rejection> {};

TEST_P(CommandLineRejects, WithOneLineNamingTheProblem) {
    std::string error;
    EXPECT_FALSE(parse(GetParam().args, error));
    EXPECT_NE(error.find(GetParam().mentions), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(BadInput, CommandLineRejects, ::testing::Values(
        Rejection{{"render", "s.gltf"}, "--out"},
        Rejection{{"render", "--out", "a.png"}, "SCENE"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--bogus"}, "--bogus"},
        Rejection{{"render", "s.gltf", "--out"}, "needs a value"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--width", "0"}, "--width"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--width", "12x"}, "--width"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--mode", "magic"}, "--mode"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--output", "all"}, "--output"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--gl", "vulkan"}, "--gl"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--camera", "1,2,3"}, "--camera"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--camera", "-1"}, "negative"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--camera", "0,0,0,0,0,0,45"}, "coincide"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "area:1"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "point:0,1,0:1,1,1:-2"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "dir:0,0,0:1,1,1:2"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "spot:0,2,0:0,-1,0:1,1,1:10:40,30"}, "cone"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "sky:1,1,1"}, "sky:r,g,b"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "sky:1,-1,1:1"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "sky:1,1,1:inf"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light", "sky:1,1,1:1:2"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,1,0:1,0,0:2,0,0:1,1,1:5"}, "non-zero"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,1,0:0,0,0:0,0,1:1,1,1:5"}, "non-zero"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,1,0:3e38,0,0:0,0,3e38:1,1,1:5"}, "finite"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,1,0:1,0,0:0,0,1:1,1,1:-5"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,nan,0:1,0,0:0,0,1:1,1,1:5"}, "--light"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--light",
                          "rect:0,1,0:1,0,0:0,0,1:1,1,1"}, "rect:cx"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--set", "x"}, "key=value"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--set", "material.specular=nan"}, "material.specular"},
        Rejection{{"render", "s.gltf", "--out", "a.tga"}, ".png"},
        Rejection{{"render", "s.gltf", "--out", "a.png", "--hdr", "a.hdr"}, ".exr"},
        Rejection{{"render", "a.gltf", "b.gltf", "--out", "a.png"}, "only one scene"},
        Rejection{{"view", "--frames", "0"}, "--frames"},
        Rejection{{"view", "--keys", "x:G"}, "--keys"},
        Rejection{{"view", "--keys", "1:G,"}, "--keys"},
        Rejection{{"view", "--drop", "scene.gltf"}, "FRAME:FILE"},
        Rejection{{"view", "--drop", "-1:scene.gltf"}, "FRAME:FILE"},
        Rejection{{"view", "--move-frames", "0"}, "--move-frames"},
        Rejection{{"view", "--out", "a.png"}, "not an option"},
        Rejection{{"view", "--mode", "reference"}, "real-time modes"},
        Rejection{{"bench", "--sweep", "huge"}, "smoke, quick or full"},
        Rejection{{"info"}, "SCENE"}));

} // namespace
} // namespace gi::app
