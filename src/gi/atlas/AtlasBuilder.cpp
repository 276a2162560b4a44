#include "gi/atlas/AtlasBuilder.h"

#include "gi/atlas/AtlasCharts.h"
#include "gi/atlas/AtlasTexcoord1.h"
#include "gi/atlas/TexelRasteriser.h"

#include <stb_rect_pack.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace gi::atlas {
namespace {

// Rectangle of a chart at `density` texels per metre, padding included. The chart starts
// half a texel inside its interior, so every texel it touches, even only along an edge or at a
// corner (conservative rasterisation), is an interior texel.
glm::ivec2 rectangleSize(const ChartLayout& chart, double density, int padding) {
    return glm::ivec2(int(std::floor(chart.extent.x * density + 0.5)) + 1 + 2 * padding,
            int(std::floor(chart.extent.y * density + 0.5)) + 1 + 2 * padding);
}

bool pack(const std::vector<ChartLayout>& charts, double density, int padding, int resolution,
        std::vector<glm::ivec2>& origins) {
    std::vector<stbrp_rect> rects(charts.size());
    for (std::size_t i = 0; i < charts.size(); ++i) {
        // rectangleSize(...) <= resolution, decided before the sizes become ints.
        const glm::dvec2 texels = charts[i].extent * density + 0.5;
        if (!(std::max(texels.x, texels.y) < resolution - 2.0 * padding)) return false;
        const glm::ivec2 size = rectangleSize(charts[i], density, padding);
        rects[i].id = int(i);
        rects[i].w = size.x;
        rects[i].h = size.y;
    }
    std::vector<stbrp_node> nodes(std::size_t(resolution) + 1);
    stbrp_context context;
    stbrp_init_target(&context, resolution, resolution, nodes.data(), int(nodes.size()));
    if (!stbrp_pack_rects(&context, rects.data(), int(rects.size()))) return false;
    origins.resize(charts.size());
    for (const stbrp_rect& r : rects) origins[std::size_t(r.id)] = glm::ivec2(r.x, r.y);
    return true;
}

// Normal and area of every triangle, with the total area and the longest edge.
std::vector<Triangle> measureTriangles(
        const AtlasMesh& mesh, double& totalArea, double& longestEdge) {
    const std::size_t triangleCount = mesh.triangleCount();
    std::vector<Triangle> triangles(triangleCount);
    totalArea = 0.0;
    longestEdge = 0.0;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
        longestEdge = std::max({longestEdge, glm::length(b - a), glm::length(c - b),
                glm::length(a - c)});
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        if (length > 0.0 && std::isfinite(length)) {
            triangles[t].normal = n / length;
            triangles[t].area = 0.5 * length;
        }
        totalArea += triangles[t].area;
    }
    return triangles;
}

// The largest density (texels per metre) at which the charts pack, by bisection between a
// failing upper bound and a fitting lower one, with the packed origins in `best`; 0 when the
// charts do not pack at any density tried.
double packedDensity(const std::vector<ChartLayout>& charts, double densityBound, int padding,
        int resolution, std::vector<glm::ivec2>& best) {
    std::vector<glm::ivec2> origins;
    double high = densityBound, low = 0.0, density = 0.85 * densityBound;
    for (int attempt = 0; attempt < 60 && low == 0.0; ++attempt) {
        if (pack(charts, density, padding, resolution, origins)) {
            low = density;
            best = origins;
        } else {
            high = density;
            density *= 0.85;
        }
    }
    if (low == 0.0) return 0.0;
    for (int step = 0; step < 7; ++step) {
        const double middle = 0.5 * (low + high);
        if (pack(charts, middle, padding, resolution, origins)) {
            low = middle;
            best = origins;
        } else {
            high = middle;
        }
    }
    return low;
}

// The atlas' charts, vertices (split along chart borders) and indices for the packed layout.
void placeCharts(const AtlasMesh& mesh, const std::vector<ChartLayout>& charts,
        const std::vector<glm::ivec2>& origins, double density, int padding, Atlas& atlas) {
    const double resolution = atlas.resolution;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOf;
    vertexOf.reserve(mesh.positions.size() * 2);
    atlas.indices.assign(mesh.triangleCount() * 3, 0);
    atlas.charts.resize(charts.size());
    for (std::size_t c = 0; c < charts.size(); ++c) {
        const ChartLayout& layout = charts[c];
        AtlasChart& chart = atlas.charts[c];
        chart.origin = origins[c];
        chart.size = rectangleSize(layout, density, padding);
        chart.normal = glm::vec3(layout.normal);
        chart.area = layout.area;
        chart.triangles = std::uint32_t(layout.triangles.size());
        const glm::dvec2 offset = glm::dvec2(chart.origin + padding) + 0.5;
        for (std::size_t i = 0; i < layout.triangles.size(); ++i) {
            const std::uint32_t t = layout.triangles[i];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t source = mesh.indices[3 * t + k];
                const std::uint64_t key = (std::uint64_t(c) << 32) | source;
                auto [it, inserted] = vertexOf.emplace(key, std::uint32_t(atlas.vertices.size()));
                if (inserted) {
                    const glm::dvec2 texel = offset + layout.corners[3 * i + k] * density;
                    atlas.vertices.push_back(
                            {source, std::uint32_t(c), glm::vec2(texel / resolution)});
                }
                atlas.indices[3 * t + k] = it->second;
            }
        }
    }
}

} // namespace

void forEachTexelCentre(
        glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, const std::function<void(int, int)>& visit) {
    rasterise(a, b, c, visit);
}

bool buildAtlas(
        const AtlasMesh& mesh, const AtlasOptions& options, Atlas& atlas, std::string& error) {
    atlas = Atlas{};
    atlas.resolution = options.resolution;
    atlas.gutter = options.gutter;
    if (mesh.triangleCount() == 0) {
        error = "the scene has no triangles to place in the atlas";
        return false;
    }
    std::string why;
    if (options.useTexcoord1 && texcoord1IsAtlas(mesh, options.resolution, why)) {
        return buildFromTexcoord1(mesh, options, atlas);
    }

    double totalArea = 0.0, longestEdge = 0.0;
    std::vector<Triangle> triangles = measureTriangles(mesh, totalArea, longestEdge);
    atlas.surfaceArea = totalArea;
    if (!(totalArea > 0.0)) {
        error = "the scene's triangles have no area";
        return false;
    }
    const double resolution = options.resolution;
    const int padding = (options.gutter + 1) / 2;
    // Upper bound of the density: the whole atlas filled without padding, and no chart longer
    // than the atlas' diagonal (a sliver's bound: without it a long thin triangle of tiny area
    // would be rasterised at an astronomical density).
    const double densityBound = std::min(
            resolution / std::sqrt(totalArea), std::sqrt(2.0) * resolution / longestEdge);
    // Slivers under a thousandth of a texel have no reliable normal: they join any chart they
    // touch (they cover no texel centre, so they cannot overlap anything there).
    const double sliver = 1e-3 / (densityBound * densityBound);
    for (Triangle& triangle : triangles) {
        if (triangle.area < sliver) triangle.normal = glm::dvec3(0.0);
    }
    // Overlap inside a chart is checked on a grid of half the expected final texel.
    const double cosLimit = std::cos(glm::radians(double(options.maxChartAngleDeg)));
    Segmentation segmentation = segment(mesh, triangles, 2.0 * densityBound * 0.8, cosLimit);
    std::vector<ChartLayout>& charts = segmentation.charts;

    const double minimumRect = double(1 + 2 * padding) * double(1 + 2 * padding);
    if (double(charts.size()) * minimumRect > resolution * resolution) {
        error = "atlas.resolution " + std::to_string(options.resolution) + " has no room for " +
                std::to_string(charts.size()) + " charts of at least " +
                std::to_string(1 + 2 * padding) +
                "^2 texels (raise atlas.resolution or lower atlas.gutter)";
        return false;
    }
    std::vector<glm::ivec2> origins;
    const double density =
            packedDensity(charts, densityBound, padding, options.resolution, origins);
    if (density == 0.0) {
        error = "could not pack " + std::to_string(charts.size()) + " charts into a " +
                std::to_string(options.resolution) + "^2 atlas";
        return false;
    }
    atlas.texelSize = 1.0 / density;
    placeCharts(mesh, charts, origins, density, padding, atlas);
    return true;
}

} // namespace gi::atlas
