// addDefaults: the documented default light and camera (SceneDefaults.h), including for an
// empty scene, and no change to scenes that bring their own.
#include "scene/SceneDefaults.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace gi::scene {
namespace {

// Values computed in float from metre-scale inputs.
constexpr float kEps = 1e-4f;

Scene sceneWithBounds(glm::vec3 min, glm::vec3 max) {
    Scene scene;
    scene.bounds.extend(min);
    scene.bounds.extend(max);
    return scene;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

TEST(SceneDefaults, AddsOnePointLightNearTheTopGivingUnitIrradianceAtTheCentre) {
    Scene scene = sceneWithBounds({-2, 0, -3}, {2, 10, 3});
    addDefaults(scene);
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_TRUE(light.isDefault);
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_EQ(light.color, glm::vec3(1.0f));
    // 90% of the way up, on the vertical axis through the centre.
    EXPECT_NEAR(light.position.x, 0.0f, kEps);
    EXPECT_NEAR(light.position.y, 9.0f, kEps);
    EXPECT_NEAR(light.position.z, 0.0f, kEps);
    const float d = glm::length(light.position - scene.bounds.center());
    EXPECT_NEAR(light.intensity / (d * d), 1.0f, kEps) << "E = I / d^2 at the centre";
}

TEST(SceneDefaults, FlatScenesGetTheLightAboveThem) {
    Scene scene = sceneWithBounds({-5, 0, -5}, {5, 0, 5});
    addDefaults(scene);
    EXPECT_NEAR(scene.lights[0].position.y, 2.5f, kEps);
    EXPECT_NEAR(scene.lights[0].intensity, 6.25f, kEps);
}

TEST(SceneDefaults, AddsACameraFramingTheBoundsFromPlusZ) {
    Scene scene = sceneWithBounds({-1, -1, -1}, {1, 1, 1});
    addDefaults(scene);
    ASSERT_EQ(scene.cameras.size(), 1u);
    const Camera& camera = scene.cameras[0];
    EXPECT_TRUE(camera.isDefault);
    EXPECT_NEAR(camera.yfov, glm::radians(45.0f), kEps);
    const glm::vec3 eye(camera.worldFromCamera[3]);
    const glm::vec3 forward = -glm::vec3(camera.worldFromCamera[2]);
    EXPECT_GT(eye.z, 1.0f);
    EXPECT_GT(eye.y, 0.0f) << "raised above the centre";
    EXPECT_NEAR(glm::dot(glm::normalize(-eye), forward), 1.0f, kEps) << "looks at the centre";
    // The bounding sphere (radius sqrt(3)) fits the vertical field of view.
    EXPECT_GE(glm::length(eye) * std::sin(camera.yfov / 2), std::sqrt(3.0f) - kEps);
    EXPECT_GT(camera.znear, 0.0f);
    EXPECT_GT(camera.zfar, glm::length(eye) + std::sqrt(3.0f));
}

TEST(SceneDefaults, EmptySceneGetsFiniteDefaults) {
    Scene scene;
    ASSERT_TRUE(scene.bounds.empty());
    addDefaults(scene);
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_TRUE(std::isfinite(scene.lights[0].position.y));
    EXPECT_GT(scene.lights[0].intensity, 0.0f);
    EXPECT_TRUE(finite(scene.cameras[0].worldFromCamera));
    EXPECT_GT(scene.cameras[0].zfar, scene.cameras[0].znear);
}

TEST(SceneDefaults, DegenerateBoundsGetFiniteDefaults) {
    for (const glm::vec3 point : {glm::vec3(0.0f), glm::vec3(1e17f, -3.0f, 2.0f)}) {
        Scene scene = sceneWithBounds(point, point);
        addDefaults(scene);
        EXPECT_TRUE(finite(scene.cameras[0].worldFromCamera));
        EXPECT_TRUE(std::isfinite(scene.lights[0].intensity));
        EXPECT_GT(scene.lights[0].intensity, 0.0f);
        EXPECT_NE(glm::vec3(scene.cameras[0].worldFromCamera[3]), point);
    }
}

TEST(SceneDefaults, KeepsLightsAndCamerasTheSceneHas) {
    Scene scene = sceneWithBounds({0, 0, 0}, {1, 1, 1});
    scene.lights.push_back(Light{});
    scene.cameras.push_back(Camera{});
    addDefaults(scene);
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.cameras.size(), 1u);
    EXPECT_FALSE(scene.lights[0].isDefault);
    EXPECT_FALSE(scene.cameras[0].isDefault);
}

} // namespace
} // namespace gi::scene
