// The Hammersley set of the atlas gather against the sequence's definition and known values
// (Wong et al. 1997, table of Phi_2), and the Cranley-Patterson offsets.
#include "gi/atlas/Hammersley.h"

#include <gtest/gtest.h>

#include <set>

namespace gi::atlas {
namespace {

TEST(Hammersley, RadicalInverseMirrorsBinaryDigits) {
    // i = 1, 2, 3, ... -> 0.1b, 0.01b, 0.11b, 0.001b, 0.101b, 0.011b, 0.111b (binary).
    const double expected[] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875, 0.0625};
    for (std::uint32_t i = 0; i < 9; ++i) EXPECT_EQ(radicalInverse2(i), expected[i]) << i;
    EXPECT_EQ(radicalInverse2(0b1011), 0.8125); // 0.1101b
    EXPECT_EQ(radicalInverse2(0x80000000u), 1.0 / 4294967296.0);
}

TEST(Hammersley, FourPointsAreTheTextbookSet) {
    const std::vector<glm::vec2> points = hammersley(4);
    ASSERT_EQ(points.size(), 4u);
    const glm::vec2 expected[] = {{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 0.25f}, {0.75f, 0.75f}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(points[std::size_t(i)], expected[i]) << i;
    }
}

// The thesis' N = 100: x = i / N exactly, y the radical inverse; every point in [0, 1)^2,
// and (a property of any (0,m,2)-net) each of the 16 strata of a 4x4 grid over the first 64
// points holds exactly 4 of them.
TEST(Hammersley, HundredPointsAreStratified) {
    const std::vector<glm::vec2> points = hammersley(100);
    ASSERT_EQ(points.size(), 100u);
    for (int i = 0; i < 100; ++i) {
        const glm::vec2 p = points[std::size_t(i)];
        EXPECT_FLOAT_EQ(p.x, float(i) / 100.0f);
        EXPECT_EQ(double(p.y), radicalInverse2(std::uint32_t(i)));
        EXPECT_GE(p.y, 0.0f);
        EXPECT_LT(p.y, 1.0f);
    }
    const std::vector<glm::vec2> net = hammersley(64);
    int strata[4][4] = {};
    for (const glm::vec2& p : net) ++strata[int(p.x * 4.0f)][int(p.y * 4.0f)];
    for (const auto& row : strata)
        for (int count : row) EXPECT_EQ(count, 4);
    EXPECT_TRUE(hammersley(0).empty());
}

TEST(Hammersley, RotationOffsetsAreDistinctAndInTheUnitSquare) {
    EXPECT_EQ(cranleyPattersonOffset(0), glm::vec2(0.0f));
    std::set<std::pair<float, float>> seen;
    for (std::uint32_t k = 0; k < 1024; ++k) {
        const glm::vec2 o = cranleyPattersonOffset(k);
        EXPECT_GE(o.x, 0.0f);
        EXPECT_LT(o.x, 1.0f);
        EXPECT_GE(o.y, 0.0f);
        EXPECT_LT(o.y, 1.0f);
        EXPECT_TRUE(seen.insert({o.x, o.y}).second) << "offset " << k << " repeats";
    }
    // R2: offset 1 = (1/g, 1/g^2), g = 1.3247179572...
    EXPECT_NEAR(cranleyPattersonOffset(1).x, 0.7548776662f, 1e-6f);
    EXPECT_NEAR(cranleyPattersonOffset(1).y, 0.5698402910f, 1e-6f);
}

} // namespace
} // namespace gi::atlas
