// The cone ring's dither period follows the filter's window (gi/voxel/RingDither.h).
#include "gi/voxel/RingDither.h"

#include <gtest/gtest.h>

namespace gi::test {
namespace {

// A 3x3 window (radius 1: a quarter of the resolution at the default voxel.filter) takes the
// 2x2 period it holds whole; wider windows and no filter at all keep the 4x4 one.
TEST(RingDither, ThreeByThreeFilterTakesTheTwoByTwoPeriodOthersTheFourByFour) {
    EXPECT_EQ(voxel::ringDitherPeriod(1), 2);
    EXPECT_EQ(voxel::ringDitherPeriod(2), 4);
    EXPECT_EQ(voxel::ringDitherPeriod(4), 4);
    EXPECT_EQ(voxel::ringDitherPeriod(0), 4);
}

} // namespace
} // namespace gi::test
