// The triangles that cast shadows for the ray-traced shadow methods (bvh, linespace): every
// triangle of every instance except the area lights' own, which must not shadow their light.
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <set>
#include <utility>
#include <vector>

namespace gi::render {

// (instance, triangle) of every emitting triangle of `lights`.
[[nodiscard]] std::set<std::pair<int, int>> emitterTriangles(const std::vector<scene::Light>& lights);

// Three world-space corners per casting triangle in its current pose (w = 0); degenerate
// triangles are left out.
[[nodiscard]] std::vector<glm::vec4> shadowCasterCorners(const scene::Scene& scene,
        const std::vector<scene::Light>& lights);

} // namespace gi::render
