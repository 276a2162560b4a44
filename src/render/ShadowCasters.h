// The triangles that cast shadows for the ray-traced shadow methods (bvh, linespace) and the
// GI modes' rays: every triangle of every instance, the area lights' own included, as in the
// path tracer. An emitting surface is opaque to every other light; its own light is not
// shadowed by it because a ray to a point drawn on it stops short of that point
// (direct_visibility.glsl: shadowRayEnd).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::render {

// Three world-space corners per casting triangle in its current pose; degenerate triangles are
// left out. Each corner's w holds, as int bits, the triangle's index in the scene's flattened
// order (instances in order, each primitive's triangles in order, degenerate ones counted):
// scene::GpuScene's and the atlas' triangle order, so a ray's hit can find its atlas texel.
[[nodiscard]] std::vector<glm::vec4> shadowCasterCorners(const scene::Scene& scene);

} // namespace gi::render
