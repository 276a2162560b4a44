// Segmentation of a mesh into atlas charts: charts grow over shared edges (vertices welded by
// position) from the largest unassigned triangle while each triangle's normal stays within the
// angle limit of the seed's and its projection overlaps nothing already in the chart; each
// chart is then turned to its minimum-area bounding rectangle (see AtlasBuilder.h).
#pragma once

#include "gi/atlas/AtlasMesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gi::atlas {

struct Triangle {
    glm::dvec3 normal{0.0}; // unit, or zero when collapsed
    double area = 0.0;
};

// A chart after segmentation: its triangles and every corner's position in the chart's
// rectangle frame (metres, from the rectangle's minimum corner).
struct ChartLayout {
    std::vector<std::uint32_t> triangles;
    std::vector<glm::dvec2> corners; // 3 per triangle, same order
    glm::dvec2 extent{0.0};          // rectangle size, metres
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double area = 0.0;
};

struct Segmentation {
    std::vector<ChartLayout> charts;
};

// Charts of `mesh`; overlap is checked on a grid of `gridScale` cells per metre, and a
// triangle joins a chart when the cosine to the seed's normal is at least `cosLimit`
// (collapsed triangles, with a zero normal, join any chart they touch).
Segmentation segment(const AtlasMesh& mesh, const std::vector<Triangle>& triangles,
        double gridScale, double cosLimit);

} // namespace gi::atlas
