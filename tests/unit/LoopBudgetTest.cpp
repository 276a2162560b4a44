// The split of a pass's loop work into draws or dispatches within llvmpipe's loop budget
// (gl/LoopBudget.h): the ranges cover every item once, in order, and none holds more items
// than the budget allows.
#include "gl/LoopBudget.h"

#include <gtest/gtest.h>

namespace gi::gl {
namespace {

void expectCoverWithinBudget(int items, int iterationsPerItem) {
    const std::vector<glm::ivec2> ranges = rangesWithinLoopBudget(items, iterationsPerItem);
    int next = 0;
    for (const glm::ivec2& range : ranges) {
        EXPECT_EQ(range.x, next) << items << " items of " << iterationsPerItem;
        EXPECT_GT(range.y, range.x) << items << " items of " << iterationsPerItem;
        EXPECT_LE(range.y - range.x, itemsWithinLoopBudget(iterationsPerItem));
        next = range.y;
    }
    EXPECT_EQ(next, std::max(items, 0)) << items << " items of " << iterationsPerItem;
}

TEST(LoopBudget, RangesCoverEveryItemWithinTheBudget) {
    for (const int items : {0, 1, 63, 64, 100, 4000, 1 << 20}) {
        for (const int perItem : {1, 2, 1027, 2569, 24577, SHADER_LOOP_ITERATIONS}) {
            expectCoverWithinBudget(items, perItem);
        }
    }
}

TEST(LoopBudget, RangesAreAsFewAsTheBudgetAllowsAndEvenlySized) {
    // 1 + a one-level visibility walk's 1028 iterations: 63 samples fit a draw.
    EXPECT_EQ(itemsWithinLoopBudget(1029), 63);
    const std::vector<glm::ivec2> ranges = rangesWithinLoopBudget(100, 1029);
    ASSERT_EQ(ranges.size(), 2u);
    EXPECT_EQ(ranges[0], glm::ivec2(0, 50));
    EXPECT_EQ(ranges[1], glm::ivec2(50, 100));
    EXPECT_EQ(rangesWithinLoopBudget(4000, 1).size(), 1u);
}

TEST(LoopBudget, AnItemOverTheBudgetStillGetsADrawOfItsOwn) {
    EXPECT_EQ(itemsWithinLoopBudget(SHADER_LOOP_ITERATIONS + 1), 1);
    EXPECT_EQ(itemsWithinLoopBudget(0), SHADER_LOOP_ITERATIONS);
    EXPECT_EQ(rangesWithinLoopBudget(3, 1 << 20).size(), 3u);
}

} // namespace
} // namespace gi::gl
