// Atlas parameterisation for any scene (SEEDS.md section 2, thesis 4.3 and 5.1): every
// triangle gets a place in one square texture, without overlap, at one texel density, so the
// atlas covers the scene's surface area uniformly — the gather samples the atlas uniformly and
// relies on that (thesis 5.1: "relative surface sizes must be kept").
//  - A scene whose TEXCOORD_1 already is such an atlas (inside [0,1]^2, no two triangles on one
//    texel centre at the atlas resolution, no collapsed triangles) keeps it.
//  - Otherwise charts are grown over shared edges (vertices welded by position) from the
//    largest unassigned triangle while each triangle's normal stays within 30 degrees of the
//    seed's and its projection onto the seed's plane overlaps no triangle already in the chart
//    (checked on a half-texel grid); each chart is rotated to its minimum-area bounding
//    rectangle and the rectangles are packed with stb_rect_pack at the largest common density
//    that fits (bisection), each padded by ceil(gutter / 2) texels, so charts are at least
//    `gutter` texels apart and dilating every chart by its padding never mixes two charts.
// CPU only, no GL: unit-testable, and cached on disk by AtlasCache.
#pragma once

#include "gi/atlas/AtlasMesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gi::atlas {

struct AtlasOptions {
    int resolution = 1024;          // texels per side of the square atlas
    int gutter = 2;                 // empty texels between the texels of any two charts
    bool useTexcoord1 = true;       // keep the scene's TEXCOORD_1 when it is a valid atlas
    float maxChartAngleDeg = 30.0f; // largest angle between a triangle and its chart's seed
};

struct AtlasVertex {
    std::uint32_t source = 0; // index into the AtlasMesh vertex arrays
    std::uint32_t chart = 0;  // index into Atlas::charts
    glm::vec2 uv{0.0f};       // atlas coordinate; texel (i, j) covers [i, i+1) x [j, j+1) / R
};

struct AtlasChart {
    glm::ivec2 origin{0}; // packed rectangle including its padding, texels
    glm::ivec2 size{0};
    glm::vec3 normal{0.0f}; // unit normal of the projection plane (seed triangle)
    double area = 0.0;      // world-space area of its triangles, m^2
    std::uint32_t triangles = 0;
};

struct Atlas {
    int resolution = 0;
    int gutter = 0;
    bool fromTexcoord1 = false;        // the scene's own TEXCOORD_1 was used
    double texelSize = 0.0;            // metres per texel edge: 1 / packing density (for TEXCOORD_1
                                       // atlases, sqrt(surface area / texels covered))
    double surfaceArea = 0.0;          // total world-space area of all triangles, m^2
    std::vector<AtlasVertex> vertices; // charts split mesh vertices along their borders
    std::vector<std::uint32_t> indices; // 3 per triangle, same triangle order as the mesh
    std::vector<AtlasChart> charts;

    std::size_t triangleCount() const { return indices.size() / 3; }
    std::uint32_t chartOf(std::size_t triangle) const {
        return vertices[indices[3 * triangle]].chart;
    }
};

// Builds the atlas; false with a message when the scene cannot fit (e.g. more charts than the
// resolution has room for, even at one texel each).
[[nodiscard]] bool buildAtlas(
        const AtlasMesh& mesh, const AtlasOptions& options, Atlas& atlas, std::string& error);

// True when the mesh's TEXCOORD_1 is usable as the atlas at `resolution`; else `why` says not.
[[nodiscard]] bool texcoord1IsAtlas(const AtlasMesh& mesh, int resolution, std::string& why);

// Calls visit(x, y) for every texel whose centre lies inside the triangle (a, b, c), given in
// texel units. Vertices are snapped to 1/256 texel and edges evaluated exactly in integers
// with a consistent tie rule, so two triangles sharing an edge never both claim a texel and
// never both miss one. Collapsed triangles claim nothing, and so do triangles wider than 2^22
// texels or beyond 2^40 texels from the origin (their edge functions would overflow).
void forEachTexelCentre(
        glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, const std::function<void(int, int)>& visit);

} // namespace gi::atlas
