// Image metrics on hand-made images whose errors are computed by hand in the comments:
// relative RMSE, mean-energy ratio, RMSE and max abs over all pixels and over a mask.
#include "reference/ImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace gi::reference {
namespace {

core::Image constantImage(int w, int h, const glm::vec3& value) {
    core::Image image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) image.set(x, y, value);
    }
    return image;
}

// Doubles: the sums are exact for these small integers and halves, so 1e-12 is rounding only.
constexpr double kEps = 1e-12;

TEST(ImageMetrics, IdenticalImagesHaveZeroError) {
    const core::Image a = constantImage(4, 3, {0.5f, 1.0f, 2.0f});
    const ImageErrors errors = measureImageError(a, a);
    EXPECT_EQ(errors.pixels, 12u);
    EXPECT_DOUBLE_EQ(errors.relativeRmse, 0.0);
    EXPECT_DOUBLE_EQ(errors.energyRatio, 1.0);
    EXPECT_DOUBLE_EQ(errors.rmse, 0.0);
    EXPECT_DOUBLE_EQ(errors.maxAbs, 0.0);
}

TEST(ImageMetrics, UniformScaleGivesRelativeErrorAndEnergyRatio) {
    // a = 1.1 b everywhere: relative RMSE = sqrt(sum (0.1 b)^2 / sum b^2) = 0.1, ratio 1.1.
    core::Image b(2, 2), a(2, 2);
    const glm::vec3 values[4] = {{1, 2, 3}, {0.5f, 0.25f, 4}, {8, 1, 0}, {2, 2, 2}};
    for (int i = 0; i < 4; ++i) {
        b.set(i % 2, i / 2, values[i]);
        a.set(i % 2, i / 2, 1.1f * values[i]);
    }
    const ImageErrors errors = measureImageError(a, b);
    EXPECT_NEAR(errors.relativeRmse, 0.1, 1e-6);   // float storage of 1.1 x value
    EXPECT_NEAR(errors.energyRatio, 1.1, 1e-6);
    EXPECT_NEAR(errors.maxAbs, 0.8, 1e-6);         // 0.1 x 8
}

TEST(ImageMetrics, HandComputedValues) {
    // b = 1 everywhere (2 pixels); a = (1,1,1) and (1,1,3): one channel off by 2.
    // sum (a-b)^2 = 4, sum b^2 = 6 -> relative RMSE sqrt(4/6); RMSE sqrt(4/6) too (n = 2,
    // 3 channels); ratio (3 + 5) / 6; max abs 2.
    core::Image b = constantImage(2, 1, glm::vec3(1.0f));
    core::Image a = b;
    a.set(1, 0, {1, 1, 3});
    const ImageErrors errors = measureImageError(a, b);
    EXPECT_NEAR(errors.relativeRmse, std::sqrt(4.0 / 6.0), kEps);
    EXPECT_NEAR(errors.rmse, std::sqrt(4.0 / 6.0), kEps);
    EXPECT_NEAR(errors.energyRatio, 8.0 / 6.0, kEps);
    EXPECT_NEAR(errors.maxAbs, 2.0, kEps);
}

TEST(ImageMetrics, MaskSelectsGeometryPixels) {
    // Pixel 1 differs hugely but its coverage is 0.5: it is not a geometry pixel.
    core::Image b = constantImage(3, 1, glm::vec3(2.0f));
    core::Image a = b;
    a.set(1, 0, glm::vec3(100.0f));
    a.set(2, 0, glm::vec3(3.0f));
    const std::vector<float> coverage = {1.0f, 0.5f, 1.0f};
    const ImageErrors masked = measureImageError(a, b, coverage);
    EXPECT_EQ(masked.pixels, 2u);
    // sum (a-b)^2 = 3 x 1, sum b^2 = 6 x 4 -> sqrt(3/24); ratio (6 + 9) / 12.
    EXPECT_NEAR(masked.relativeRmse, std::sqrt(3.0 / 24.0), kEps);
    EXPECT_NEAR(masked.energyRatio, 15.0 / 12.0, kEps);
    EXPECT_NEAR(masked.maxAbs, 1.0, kEps);
    const ImageErrors all = measureImageError(a, b);
    EXPECT_EQ(all.pixels, 3u);
    EXPECT_NEAR(all.maxAbs, 98.0, kEps);
    // A lower threshold admits the half-covered pixel.
    EXPECT_EQ(measureImageError(a, b, coverage, 0.4f).pixels, 3u);
}

TEST(ImageMetrics, DegenerateInputs) {
    const core::Image zero = constantImage(2, 2, glm::vec3(0.0f));
    const core::Image one = constantImage(2, 2, glm::vec3(1.0f));
    ImageErrors errors = measureImageError(zero, zero);
    EXPECT_DOUBLE_EQ(errors.relativeRmse, 0.0);
    EXPECT_DOUBLE_EQ(errors.energyRatio, 1.0);
    errors = measureImageError(one, zero);
    EXPECT_TRUE(std::isinf(errors.relativeRmse));
    EXPECT_TRUE(std::isinf(errors.energyRatio));

    errors = measureImageError(one, constantImage(2, 3, glm::vec3(1.0f)));
    EXPECT_TRUE(errors.sizeMismatch);
    EXPECT_TRUE(std::isnan(errors.relativeRmse));
    const std::vector<float> wrongMask(3, 1.0f);
    EXPECT_TRUE(measureImageError(one, one, wrongMask).sizeMismatch);

    const std::vector<float> empty(4, 0.0f);
    errors = measureImageError(one, one, empty);
    EXPECT_EQ(errors.pixels, 0u);
    EXPECT_TRUE(std::isnan(errors.relativeRmse));

    core::Image bad = one;
    bad.rgb[0] = std::numeric_limits<float>::quiet_NaN();
    errors = measureImageError(bad, one);
    EXPECT_TRUE(std::isnan(errors.relativeRmse));
    EXPECT_TRUE(std::isnan(errors.maxAbs));
}

} // namespace
} // namespace gi::reference
