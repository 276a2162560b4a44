// Pre-exposure (scene/Exposure.h): a power of two that brings the scene's characteristic
// irradiance to about 1, whatever the units of the lights.
#include "scene/Exposure.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gi::scene {
namespace {

Aabb unitBox() {
    Aabb box;
    box.min = glm::vec3(0.0f);
    box.max = glm::vec3(1.0f);
    return box;
}

Light point(float intensity) {
    Light light;
    light.type = LightType::Point;
    light.intensity = intensity;
    return light;
}

TEST(Exposure, IsAPowerOfTwoNearTheInverseIrradiance) {
    for (float intensity : {1e-6f, 0.3f, 1.0f, 1e7f}) {
        const float k = preExposure({point(intensity)}, unitBox(), 0.0f);
        int exponent = 0;
        EXPECT_EQ(std::frexp(k, &exponent), 0.5f) << "not a power of two: " << k;
        // The unit box's diagonal is sqrt(3): E = I / 3, and k E is within a factor sqrt(2).
        const float exposed = k * intensity / 3.0f;
        EXPECT_GE(exposed, 1.0f / std::sqrt(2.0f) * 0.999f) << intensity;
        EXPECT_LE(exposed, std::sqrt(2.0f) * 1.001f) << intensity;
    }
}

TEST(Exposure, ScalesWithTheSceneSoScaledScenesMatch) {
    // A scene scaled by s with its light scaled by s^2 has the same irradiance everywhere and
    // so the same exposure.
    Aabb big = unitBox();
    big.max = glm::vec3(1e4f);
    EXPECT_EQ(preExposure({point(1e8f)}, big, 0.0f), preExposure({point(1.0f)}, unitBox(), 0.0f));
}

TEST(Exposure, DirectionalLightsAndEmissionCount) {
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 1e5f;
    EXPECT_EQ(preExposure({sun}, unitBox(), 0.0f), std::ldexp(1.0f, -17));   // 1e5 ~ 2^16.6
    EXPECT_EQ(preExposure({}, unitBox(), 1000.0f / float(M_PI)), std::ldexp(1.0f, -10));
}

TEST(Exposure, DarkOrBrokenScenesUseOne) {
    EXPECT_EQ(preExposure({}, unitBox(), 0.0f), 1.0f);
    EXPECT_EQ(preExposure({point(0.0f)}, unitBox(), 0.0f), 1.0f);
    EXPECT_EQ(preExposure({point(NAN)}, unitBox(), 0.0f), 1.0f);
    EXPECT_EQ(preExposure({point(INFINITY)}, unitBox(), 0.0f), 1.0f);
    // Beyond 2^64 the factor stops: k times a half float must stay a finite float.
    EXPECT_EQ(preExposure({point(1e30f)}, unitBox(), 0.0f), std::ldexp(1.0f, -64));
}

} // namespace
} // namespace gi::scene
