// The window a directional light sees a box through: an orthographic view along the light
// whose window is the box's outline seen from the light, turned so that one of the box's
// axes runs up the window (whichever gives the smallest window), instead of the square around
// the box's bounding sphere. Sponza's box (22.9 x 15.6 x 37.2 m) under a sun along
// (0.2, -1, 0.3) gives a window of 40.1 x 27.3 m against the sphere's 46.4 m square, so the
// same pixels cover it more finely. Shadow maps (render/ShadowPass), voxel injection and
// reflective shadow maps (LightViews.h) all see a sun through it.
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::scene {

struct SunWindow {
    glm::mat4 view{1.0f}, projection{1.0f};   // world -> light view -> clip
    glm::vec2 size{1.0f};                     // the window's sides, metres (x, y of the view)
    float depth = 1.0f;                       // near to far, metres
};

// The window over `box` for light travelling along unit `direction`; for an empty box, a
// window of 2 m around the origin.
[[nodiscard]] SunWindow sunWindow(const glm::vec3& direction, const Aabb& box);

} // namespace gi::scene
