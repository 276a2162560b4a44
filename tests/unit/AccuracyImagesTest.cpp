// The scoreboard's error maps are signed: light a render gains shows red, light it loses
// blue, a match black, and the strength saturates at the reference's mean.
#include "bench/AccuracyImages.h"

#include <gtest/gtest.h>

#include <limits>

namespace gi::bench {
namespace {

TEST(AccuracyImages, ErrorMapShowsGainedLightRedAndLostLightBlue) {
    const glm::vec3 gained = signedErrorColour(0.5f, 1.0f);
    const glm::vec3 lost = signedErrorColour(-0.5f, 1.0f);
    EXPECT_FLOAT_EQ(gained.r, 0.5f);
    EXPECT_FLOAT_EQ(gained.b, 0.0f);
    EXPECT_FLOAT_EQ(lost.b, 0.5f);
    EXPECT_FLOAT_EQ(lost.r, 0.0f);
    EXPECT_EQ(signedErrorColour(0.0f, 1.0f), glm::vec3(0.0f));
}

TEST(AccuracyImages, ErrorMapSaturatesAtTheReferencesMean) {
    EXPECT_FLOAT_EQ(signedErrorColour(2.0f, 0.5f).r, 1.0f);
    EXPECT_FLOAT_EQ(signedErrorColour(-7.0f, 0.5f).b, 1.0f);
    EXPECT_FLOAT_EQ(signedErrorColour(0.25f, 0.5f).r, 0.5f);
}

TEST(AccuracyImages, ErrorMapIsBlackWithoutAScaleOrANumber) {
    EXPECT_EQ(signedErrorColour(1.0f, 0.0f), glm::vec3(0.0f));
    EXPECT_EQ(signedErrorColour(std::numeric_limits<float>::quiet_NaN(), 1.0f), glm::vec3(0.0f));
}

} // namespace
} // namespace gi::bench
