// glTF animations on the scene model (scene/Animation.h) and their validation by the loader:
// interpolation per glTF 2.0 section 3.11, which instances become dynamic, the pose at a time,
// bounds over every pose, and one clear error per malformed channel.
#include "scene/Animation.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

namespace gi::scene {
namespace {

const std::string kAnimated =
        std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box_animated.gltf";

AnimationChannel channel(AnimationInterpolation interpolation, AnimationPath path,
        std::vector<float> times, std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.node = 0;
    c.path = path;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

TEST(Animation, LinearStepAndClamping) {
    const AnimationChannel linear = channel(AnimationInterpolation::Linear,
            AnimationPath::Translation, {1.0f, 3.0f}, {glm::vec4(0.0f), glm::vec4(4.0f)});
    EXPECT_EQ(sampleChannel(linear, 2.0f), glm::vec4(2.0f));
    EXPECT_EQ(sampleChannel(linear, 0.0f), glm::vec4(0.0f)) << "before the first key";
    EXPECT_EQ(sampleChannel(linear, 9.0f), glm::vec4(4.0f)) << "after the last key";
    AnimationChannel step = linear;
    step.interpolation = AnimationInterpolation::Step;
    EXPECT_EQ(sampleChannel(step, 2.9f), glm::vec4(0.0f));
}

TEST(Animation, RotationsSlerp) {
    const float s = std::sin(glm::radians(45.0f)), c = std::cos(glm::radians(45.0f));
    // 0 -> 90 degrees about +Y; halfway is 45 degrees, a unit quaternion (lerp would not be).
    const AnimationChannel turn = channel(AnimationInterpolation::Linear, AnimationPath::Rotation,
            {0.0f, 1.0f}, {glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(0.0f, s, 0.0f, c)});
    const glm::vec4 half = sampleChannel(turn, 0.5f);
    EXPECT_NEAR(half.y, std::sin(glm::radians(22.5f)), 1e-6f);
    EXPECT_NEAR(half.w, std::cos(glm::radians(22.5f)), 1e-6f);
}

TEST(Animation, CubicSplineFollowsTheHermiteBasis) {
    // Keys 0 and 1 at t = 0 and 2 with out-tangent 1 and in-tangent 0: at the middle the
    // Hermite basis gives p0/2 + (dt * m0)/8 + p1/2 - (dt * m1)/8 = 0.5 + 0.25 = 0.75.
    const AnimationChannel spline = channel(AnimationInterpolation::CubicSpline,
            AnimationPath::Translation, {0.0f, 2.0f},
            {glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(1.0f),    // in, value, out of key 0
             glm::vec4(0.0f), glm::vec4(1.0f), glm::vec4(0.0f)});  // in, value, out of key 1
    EXPECT_NEAR(sampleChannel(spline, 1.0f).x, 0.75f, 1e-6f);
    EXPECT_EQ(sampleChannel(spline, 2.0f).x, 1.0f);
}

TEST(Animation, AnimatedCornellBoxHasOneDynamicCubeThatMoves) {
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(loadGltf(kAnimated, scene, error, warnings)) << error;
    ASSERT_EQ(scene.animations.size(), 2u);
    EXPECT_FLOAT_EQ(animationDuration(scene), 4.0f);
    const Instance* cube = nullptr;
    for (const Instance& instance : scene.instances) {
        if (instance.dynamic) {
            EXPECT_EQ(cube, nullptr) << "only the cube is dynamic";
            cube = &instance;
        }
    }
    ASSERT_NE(cube, nullptr);
    poseScene(scene, 0.0);
    EXPECT_NEAR(cube->worldFromLocal[3].x, 0.10f, 1e-6f);
    poseScene(scene, 2.0);
    EXPECT_NEAR(cube->worldFromLocal[3].x, 0.50f, 1e-6f);
    poseScene(scene, 5.0);   // loops: 5 s is 1 s into the next cycle
    EXPECT_NEAR(cube->worldFromLocal[3].x, 0.30f, 1e-6f);
    // The cube turns about +Y: at 2 s by 90 degrees, so its local +X points along -Z.
    poseScene(scene, 2.0);
    EXPECT_NEAR(cube->worldFromLocal[0].z, -1.0f, 1e-6f);
    // The bounds hold the cube at both ends of its slide (half-size 0.04 m, turned 45 degrees
    // on the way, so up to 0.04 sqrt(2) off its centre).
    EXPECT_LE(scene.bounds.min.x, 0.10f - 0.04f + 1e-6f);
    EXPECT_GE(scene.bounds.max.z, -0.05f + 0.04f * std::sqrt(2.0f) - 1e-3f);
}

// Writes the animated Cornell box with `change` applied to its JSON and loads it.
std::string loadEdited(const std::function<void(nlohmann::json&)>& change) {
    std::ifstream in(kAnimated);
    nlohmann::json doc = nlohmann::json::parse(in);
    change(doc);
    const std::string path = std::string(VOXATLAS_TEST_OUTPUT_DIR) + "/animation_edit.gltf";
    std::filesystem::create_directories(VOXATLAS_TEST_OUTPUT_DIR);
    std::ofstream(path) << doc.dump();
    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_FALSE(loadGltf(path, scene, error, warnings)) << "the broken file loaded";
    return error;
}

TEST(Animation, LoaderRefusesMalformedChannels) {
    EXPECT_NE(loadEdited([](nlohmann::json& d) {
        d["animations"][0]["channels"][0]["target"]["path"] = "colour";
    }).find("target.path 'colour'"), std::string::npos);
    EXPECT_NE(loadEdited([](nlohmann::json& d) {
        d["animations"][0]["channels"][0]["target"]["node"] = 999;
    }).find("target.node"), std::string::npos);
    EXPECT_NE(loadEdited([](nlohmann::json& d) {
        d["animations"][0]["samplers"][0]["interpolation"] = "BEZIER";
    }).find("interpolation 'BEZIER'"), std::string::npos);
    // The rotation channel's output (VEC4) driving a translation (VEC3).
    EXPECT_NE(loadEdited([](nlohmann::json& d) {
        d["animations"][1]["channels"][0]["target"]["path"] = "translation";
    }).find("translation needs"), std::string::npos);
    // glTF forbids animating a node given by a matrix.
    const std::string matrixError = loadEdited([](nlohmann::json& d) {
        const int node = d["animations"][0]["channels"][0]["target"]["node"];
        d["nodes"][node].erase("translation");
        d["nodes"][node]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    });
    EXPECT_NE(matrixError.find("has a matrix"), std::string::npos) << matrixError;
    EXPECT_NE(loadEdited([](nlohmann::json& d) {
        d["animations"][0]["samplers"][0]["input"] = d["animations"][0]["samplers"][0]["output"];
    }).find("SCALAR"), std::string::npos);
}

} // namespace
} // namespace gi::scene
