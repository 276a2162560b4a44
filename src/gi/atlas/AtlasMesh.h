// The scene flattened into one world-space triangle list, in exactly the vertex and triangle
// order of scene::GpuScene's buffers (instances in order, each primitive's triangles in order,
// the same winding). The atlas builder works on it without GL, and the atlas vertex buffer
// keeps its triangle order, so GpuScene's per-draw index ranges address the same triangles in
// both buffers and the atlas passes reuse GpuScene's draws (materials, textures, culling).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gi::atlas {

struct AtlasMesh {
    std::vector<glm::vec3> positions; // world space, metres
    std::vector<glm::vec3> normals;   // world space, unit
    std::vector<glm::vec2> texcoords0;
    std::vector<glm::vec2> texcoords1;     // zero where a primitive has no TEXCOORD_1
    std::vector<glm::vec4> colors;         // linear RGBA, white when absent
    std::vector<std::uint8_t> doubleSided; // per vertex: 1 if its material is double-sided
    std::vector<std::uint32_t> indices;    // 3 per triangle, into the vertex arrays
    bool hasTexcoord1 = false;             // every primitive with triangles has TEXCOORD_1

    std::size_t triangleCount() const { return indices.size() / 3; }
};

[[nodiscard]] AtlasMesh flattenScene(const scene::Scene& scene);

// World-space area of triangle t (m^2).
[[nodiscard]] double triangleArea(const AtlasMesh& mesh, std::size_t t);

} // namespace gi::atlas
