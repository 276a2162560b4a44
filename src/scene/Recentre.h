// Float precision far from the origin. A float holds about 7 digits: at 1e5 m a vertex lands
// on an 8 mm grid, shadow-map depths and voxel coordinates lose their fractions, and a Cornell
// box there renders with torn walls and streaked shadows. A scene whose centre lies far from
// the origin, measured in its own size, is therefore moved next to the origin once at load:
// every instance transform, light, camera and the bounds shift by `origin`, a whole number of
// metres (exact in float, so each shift is an exact float subtraction of nearby numbers).
// Positions the user gives (--camera, --light) are in file coordinates; subtract the origin.
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::scene {

// Where the scene's coordinates were moved from: the file's point that is now (0, 0, 0).
// Zero when the scene was near the origin already.
[[nodiscard]] glm::vec3 recentreFarScene(Scene& scene);

// True when `centre` lies so far from the origin, relative to `size` (the bounds' diagonal),
// that float positions would lose detail a pixel could show.
[[nodiscard]] bool isFarFromOrigin(const glm::vec3& centre, float size);

} // namespace gi::scene
