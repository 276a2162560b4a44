// The cone ring's dither follows the filter's window (gi/voxel/RingDither.h).
#include "gi/voxel/RingDither.h"

#include <gtest/gtest.h>

namespace gi::test {
namespace {

using voxel::RingDither;
using voxel::ringDither;

// The default radius scaled to the trace: 1 at a quarter of the resolution (3x3 window: no
// dither), 2 at half (5x5), 4 at full (9x9); no filter keeps the 4x4 dither of single pixels.
TEST(RingDither, TurnsAndCellsFromTheFiltersWindow) {
    EXPECT_EQ(ringDither(1), (RingDither{1, 1}));
    EXPECT_EQ(ringDither(2), (RingDither{2, 2}));
    EXPECT_EQ(ringDither(4), (RingDither{4, 2}));
    EXPECT_EQ(ringDither(0), (RingDither{4, 1}));
}

// Every pixel's window averages every turn: a whole period (turns x cell pixels) fits in it,
// and the code cone_trace.frag decodes says the same.
TEST(RingDither, EveryWindowHoldsAWholePeriod) {
    for (int radius = 2; radius <= 16; ++radius) {
        const RingDither d = ringDither(radius);
        EXPECT_LE(d.turns * d.cell, 2 * radius + 1) << "radius " << radius;
        EXPECT_TRUE(d.turns == 2 || d.turns == 4) << "radius " << radius;
        EXPECT_EQ(d.code() / 8, d.turns);
        EXPECT_EQ(d.code() % 8, d.cell);
    }
}

} // namespace
} // namespace gi::test
