// The window a sun sees the scene through (scene/SunWindow.h): every corner of the box inside
// the view volume, and no larger than it has to be.
#include "scene/SunWindow.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>

namespace gi::scene {
namespace {

Aabb sponzaBox() {
    Aabb box;
    box.min = {-11.83f, -1.264f, -18.0f};
    box.max = {11.05f, 14.29f, 19.21f};
    return box;
}

TEST(SunWindow, HoldsEveryCornerOfTheBoxForAnyDirection) {
    const Aabb box = sponzaBox();
    const glm::vec3 directions[] = {{0.2f, -1.0f, 0.3f}, {0.0f, -1.0f, 0.0f}, {1.0f, 0.0f, 0.0f},
            {0.0f, 0.0f, -1.0f}, {-0.5f, -0.3f, 0.8f}, {0.577f, 0.577f, 0.577f}};
    for (glm::vec3 d : directions) {
        d = glm::normalize(d);
        const SunWindow w = sunWindow(d, box);
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                    (i & 4) ? box.max.z : box.min.z);
            const glm::vec4 clip = w.projection * w.view * glm::vec4(corner, 1.0f);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_LE(std::abs(clip[axis] / clip.w), 1.0f)
                        << "corner " << i << " axis " << axis << " for direction (" << d.x << ", "
                        << d.y << ", " << d.z << ")";
            }
        }
        // Never larger than the square around the bounding sphere it replaced.
        EXPECT_LE(std::max(w.size.x, w.size.y), glm::length(box.size()) * 1.002f);
    }
}

TEST(SunWindow, IsTheBoxOutlineWithABoxAxisUpTheWindow) {
    // The suite's sun over Sponza: up = x gives 40.1 x 27.3 m (up = y 39.7 x 46.3, up = z
    // 25.5 x 41.3), each side a thousandth wider for the margin.
    const SunWindow w = sunWindow(glm::normalize(glm::vec3(0.2f, -1.0f, 0.3f)), sponzaBox());
    EXPECT_NEAR(std::max(w.size.x, w.size.y), 40.11f * 1.002f, 0.05f);
    EXPECT_NEAR(std::min(w.size.x, w.size.y), 27.29f * 1.002f, 0.05f);
    // Straight down on a box: its own footprint.
    Aabb flat;
    flat.min = {0.0f, 0.0f, 0.0f};
    flat.max = {4.0f, 1.0f, 2.0f};
    const SunWindow down = sunWindow(glm::vec3(0.0f, -1.0f, 0.0f), flat);
    EXPECT_NEAR(std::max(down.size.x, down.size.y), 4.0f * 1.002f, 1e-3f);
    EXPECT_NEAR(std::min(down.size.x, down.size.y), 2.0f * 1.002f, 1e-3f);
    // In depth a hundredth of the diagonal (4.58 m) on either side.
    EXPECT_NEAR(down.depth, 1.0f + 2.0f * 0.01f * glm::length(flat.size()), 1e-3f);
}

TEST(SunWindow, LeavesRoomInDepthAboveAndBelowAFlatScene) {
    // A lone 2 m floor under a sun overhead: the box has no height, and shading looks the map
    // up from points pushed a few texels off the floor (1.5 texels of 2 m / 4096 is 0.7 mm;
    // 1 cm here). Those must lie inside the window's depth, not beyond its near plane.
    Aabb floor;
    floor.min = {-1.0f, 0.0f, -1.0f};
    floor.max = {1.0f, 0.0f, 1.0f};
    const SunWindow w = sunWindow(glm::vec3(0.0f, -1.0f, 0.0f), floor);
    EXPECT_GT(w.depth, 0.05f);
    for (const float height : {-0.01f, 0.0f, 0.01f}) {
        const glm::vec4 clip = w.projection * w.view * glm::vec4(0.3f, height, -0.2f, 1.0f);
        EXPECT_LT(std::abs(clip.z / clip.w), 0.9f) << "a point " << height << " m off the floor";
    }
}

} // namespace
} // namespace gi::scene
