// When a draw made for what one view sees (the VPLs', the atlas senders') is made again:
// scene::viewMovedFarFrom's thresholds, each on its own.
#include "scene/CameraView.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace gi::scene {
namespace {

constexpr float kDiagonal = 10.0f;   // 5 % of it: 0.5 m

CameraView viewFrom(const glm::vec3& eye, const glm::vec3& target, float yfovDegrees = 60.0f,
        float aspect = 1.5f) {
    Aabb bounds;
    bounds.extend(glm::vec3(-5.0f));
    bounds.extend(glm::vec3(5.0f));
    return cameraLookAt(eye, target, glm::radians(yfovDegrees), aspect, bounds);
}

TEST(ViewMoved, AStillOrSlightlyMovedViewKeepsTheDraw) {
    const CameraView view = viewFrom({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f});
    EXPECT_FALSE(viewMovedFarFrom(view, view, kDiagonal));
    EXPECT_FALSE(viewMovedFarFrom(view, viewFrom({0.4f, 1.0f, 3.0f}, {0.4f, 1.0f, 0.0f}),
            kDiagonal)) << "0.4 m sideways";
    EXPECT_FALSE(viewMovedFarFrom(view, viewFrom({0.0f, 1.0f, 3.0f}, {0.35f, 1.0f, 0.0f}),
            kDiagonal)) << "turned 6.7 degrees";
    EXPECT_FALSE(viewMovedFarFrom(view, viewFrom({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, 63.0f),
            kDiagonal)) << "zoomed 5 %";
}

TEST(ViewMoved, AStrideATurnAZoomOrAnotherShapeRedoesIt) {
    const CameraView view = viewFrom({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f});
    EXPECT_TRUE(viewMovedFarFrom(view, viewFrom({0.6f, 1.0f, 3.0f}, {0.6f, 1.0f, 0.0f}),
            kDiagonal)) << "0.6 m sideways";
    EXPECT_TRUE(viewMovedFarFrom(view, viewFrom({0.0f, 1.0f, 3.0f}, {0.7f, 1.0f, 0.0f}),
            kDiagonal)) << "turned 13 degrees";
    EXPECT_TRUE(viewMovedFarFrom(view, viewFrom({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, 70.0f),
            kDiagonal)) << "zoomed 17 %";
    EXPECT_TRUE(viewMovedFarFrom(view,
            viewFrom({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, 60.0f, 1.0f), kDiagonal))
            << "another aspect ratio";
}

} // namespace
} // namespace gi::scene
