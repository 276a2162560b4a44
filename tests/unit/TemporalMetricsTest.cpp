// The temporal bench's figures (bench/TemporalMetrics.h) on hand-made frames.
#include "bench/TemporalMetrics.h"

#include <gtest/gtest.h>

namespace gi::bench {
namespace {

CoveredFrame uniformFrame(float value, int width = 4, int height = 2) {
    CoveredFrame frame{core::Image(width, height),
            std::vector<float>(std::size_t(width * height), 1.0f)};
    for (float& v : frame.image.rgb) v = value;
    return frame;
}

TEST(TemporalMetrics, FrameChangeIsMeanAbsoluteChangeOverMeanLevel) {
    EXPECT_DOUBLE_EQ(relativeFrameChange(uniformFrame(1.0f), uniformFrame(1.0f)), 0.0);
    // |3 - 1| / ((1 + 3) / 2) = 1.
    EXPECT_NEAR(relativeFrameChange(uniformFrame(1.0f), uniformFrame(3.0f)), 1.0, 1e-6);
    CoveredFrame a = uniformFrame(1.0f), b = uniformFrame(1.0f);
    b.image.set(0, 0, glm::vec3(2.0f));   // one pixel of eight changes by 1
    EXPECT_NEAR(relativeFrameChange(a, b), 1.0 / 8.5, 1e-6);
}

TEST(TemporalMetrics, FrameChangeCountsOnlyPixelsCoveredInBoth) {
    CoveredFrame a = uniformFrame(1.0f), b = uniformFrame(1.0f);
    b.image.set(0, 0, glm::vec3(100.0f));
    b.coverage[0] = 0.0f;   // the background in b: not compared
    EXPECT_DOUBLE_EQ(relativeFrameChange(a, b), 0.0);
    EXPECT_NEAR(meanFrameChange({uniformFrame(1.0f), uniformFrame(3.0f), uniformFrame(3.0f)}), 0.5,
            1e-6);
    EXPECT_DOUBLE_EQ(meanFrameChange({uniformFrame(1.0f)}), 0.0);
}

TEST(TemporalMetrics, TrailIsMeanDifferenceOverTheRegionRelativeToTheFloor) {
    CoveredFrame fresh = uniformFrame(1.0f), history = uniformFrame(1.0f);
    history.image.set(1, 0, glm::vec3(1.5f));
    std::vector<bool> region(8, false);
    region[1] = region[2] = true;
    // (0.5 + 0) / 2 pixels / floor light 2.
    EXPECT_NEAR(trailBrightness(history, fresh, region, 2.0), 0.125, 1e-6);
    EXPECT_DOUBLE_EQ(trailBrightness(history, fresh, std::vector<bool>(8, false), 2.0), 0.0);
}

TEST(TemporalMetrics, FloorRowsAndChangedPixels) {
    CoveredFrame frame = uniformFrame(1.0f);
    for (int x = 0; x < 4; ++x) frame.image.set(x, 1, glm::vec3(3.0f));
    EXPECT_NEAR(meanLuminanceOfRows(frame, 1), 3.0, 1e-6);
    EXPECT_NEAR(meanLuminanceOfRows(frame, 0), 2.0, 1e-6);
    const std::vector<bool> changed = changedPixels(uniformFrame(1.0f), frame, 0.5);
    EXPECT_FALSE(changed[0]);
    EXPECT_TRUE(changed[4]);
}

} // namespace
} // namespace gi::bench
