// The viewer's frame-budget controller against a synthetic frame cost: fixed ms plus ms per
// full-resolution area, so convergence, hysteresis and refinement are checked exactly.
#include "app/ResolutionController.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace gi::app {
namespace {

struct Cost {
    double fixedMs;
    double fullAreaMs;   // pixel-proportional part at scale 1
    double operator()(float scale) const { return fixedMs + fullAreaMs * scale * scale; }
};

// Runs `frames` frames with the camera moving (or not); returns the last frame's time.
double runFrames(ResolutionController& controller, const Cost& cost, int frames, bool moving,
        std::set<float>* scales = nullptr) {
    double ms = 0.0;
    for (int i = 0; i < frames; ++i) {
        const float scale = controller.beginFrame(moving);
        if (scales) scales->insert(scale);
        ms = cost(scale);
        controller.endFrame(ms);
    }
    return ms;
}

TEST(ResolutionController, MovingFramesSettleWithinTheBudgetBand) {
    for (const Cost cost : {Cost{5.0, 400.0}, Cost{40.0, 800.0}, Cost{0.0, 2000.0}}) {
        ResolutionController controller(100.0);
        runFrames(controller, cost, 3, false);
        runFrames(controller, cost, 10, true);
        const double ms = runFrames(controller, cost, 1, true);
        EXPECT_NEAR(ms, 100.0, 100.0 * ResolutionController::kTolerance + 10.0)
                << "fixed " << cost.fixedMs << " area " << cost.fullAreaMs;
        EXPECT_LT(controller.scale(), 1.0f);
        EXPECT_TRUE(controller.moving());
    }
}

TEST(ResolutionController, SettledScaleDoesNotOscillate) {
    ResolutionController controller(100.0);
    const Cost cost{10.0, 500.0};
    runFrames(controller, cost, 3, false);
    runFrames(controller, cost, 10, true);
    std::set<float> scales;
    runFrames(controller, cost, 50, true, &scales);
    EXPECT_EQ(scales.size(), 1u);
}

TEST(ResolutionController, NoiseWithinTheDeadBandKeepsTheScale) {
    ResolutionController controller(100.0);
    const Cost cost{10.0, 500.0};
    runFrames(controller, cost, 3, false);
    runFrames(controller, cost, 10, true);
    const float settled = controller.scale();
    const double base = cost(settled);
    ASSERT_NEAR(base, 100.0, 10.0);
    // Alternating +-5% keeps every median inside the +-15% band around the budget.
    for (int i = 0; i < 40; ++i) {
        EXPECT_EQ(controller.beginFrame(true), settled);
        controller.endFrame(base * (i % 2 ? 1.05 : 0.95));
    }
}

TEST(ResolutionController, StillViewRefinesToFullResolution) {
    ResolutionController controller(100.0);
    const Cost cost{5.0, 600.0};
    runFrames(controller, cost, 3, false);
    runFrames(controller, cost, 10, true);
    ASSERT_LT(controller.scale(), 1.0f);
    // One unchanged frame is still treated as motion (a pause between input events).
    EXPECT_EQ(controller.beginFrame(false), controller.scale());
    EXPECT_TRUE(controller.moving());
    controller.endFrame(100.0);
    EXPECT_EQ(controller.beginFrame(false), 1.0f);
    EXPECT_FALSE(controller.moving());
    controller.endFrame(cost(1.0f));
}

TEST(ResolutionController, ScreenshotFramesAreFullResolution) {
    ResolutionController controller(100.0);
    const Cost cost{5.0, 600.0};
    runFrames(controller, cost, 3, false);
    runFrames(controller, cost, 10, true);
    EXPECT_EQ(controller.beginFrame(true, true), 1.0f);
    EXPECT_FALSE(controller.moving());
}

TEST(ResolutionController, CheapFramesStayAtFullResolution) {
    ResolutionController controller(100.0);
    const Cost cost{5.0, 40.0};
    std::set<float> scales;
    runFrames(controller, cost, 3, false, &scales);
    runFrames(controller, cost, 20, true, &scales);
    EXPECT_EQ(scales, std::set<float>{1.0f});
}

TEST(ResolutionController, UnreachableBudgetStopsAtTheMinimumScale) {
    ResolutionController controller(100.0);
    const Cost cost{150.0, 5000.0};   // the fixed cost alone is over the budget
    runFrames(controller, cost, 3, false);
    runFrames(controller, cost, 30, true);
    EXPECT_FLOAT_EQ(controller.scale(), ResolutionController::kMinScale);
}

TEST(ResolutionController, NoBudgetMeansFullResolution) {
    ResolutionController controller(0.0);
    EXPECT_FALSE(controller.enabled());
    const Cost cost{5.0, 5000.0};
    std::set<float> scales;
    runFrames(controller, cost, 10, true, &scales);
    EXPECT_EQ(scales, std::set<float>{1.0f});
}

TEST(ResolutionController, ScaledSizeRoundsAndKeepsAPixel) {
    EXPECT_EQ(ResolutionController::scaledSize({1280, 720}, 1.0f), glm::ivec2(1280, 720));
    EXPECT_EQ(ResolutionController::scaledSize({1280, 720}, 0.5f), glm::ivec2(640, 360));
    EXPECT_EQ(ResolutionController::scaledSize({3, 1}, 0.125f), glm::ivec2(1, 1));
}

} // namespace
} // namespace gi::app
