#include "gi/atlas/AtlasTexcoord1.h"

#include "gi/atlas/TexelRasteriser.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace gi::atlas {

bool texcoord1IsAtlas(const AtlasMesh& mesh, int resolution, std::string& why) {
    if (!mesh.hasTexcoord1) {
        why = "the scene has no TEXCOORD_1 on every primitive";
        return false;
    }
    for (const glm::vec2& uv : mesh.texcoords1) {
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y) || uv.x < 0.0f || uv.y < 0.0f ||
                uv.x > 1.0f || uv.y > 1.0f) {
            why = "TEXCOORD_1 leaves the unit square";
            return false;
        }
    }
    const std::size_t r = std::size_t(resolution);
    std::vector<std::uint64_t> claimed((r * r + 63) / 64, 0);
    bool overlap = false;
    const double scale = resolution;
    for (std::size_t t = 0; t < mesh.triangleCount() && !overlap; ++t) {
        const glm::dvec2 a = glm::dvec2(mesh.texcoords1[mesh.indices[3 * t]]) * scale;
        const glm::dvec2 b = glm::dvec2(mesh.texcoords1[mesh.indices[3 * t + 1]]) * scale;
        const glm::dvec2 c = glm::dvec2(mesh.texcoords1[mesh.indices[3 * t + 2]]) * scale;
        const glm::dvec2 u = b - a, v = c - a;
        if (u.x * v.y - u.y * v.x == 0.0 && triangleArea(mesh, t) > 0.0) {
            why = "TEXCOORD_1 collapses triangle " + std::to_string(t);
            return false;
        }
        rasterise(a, b, c, [&](int x, int y) {
            if (x < 0 || y < 0 || x >= resolution || y >= resolution) return;
            const std::size_t i = std::size_t(y) * r + std::size_t(x);
            if ((claimed[i / 64] >> (i % 64)) & 1u) overlap = true;
            claimed[i / 64] |= std::uint64_t(1) << (i % 64);
        });
    }
    if (overlap) {
        why = "TEXCOORD_1 overlaps itself at " + std::to_string(resolution) + "^2";
        return false;
    }
    return true;
}

bool buildFromTexcoord1(const AtlasMesh& mesh, const AtlasOptions& options, Atlas& atlas) {
    const std::size_t triangleCount = mesh.triangleCount();
    // Charts are the connected components of triangles sharing vertices (and so TEXCOORD_1).
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t a = find(mesh.indices[3 * t]);
        for (int k = 1; k < 3; ++k) {
            const std::uint32_t b = find(mesh.indices[3 * t + k]);
            if (a != b) parent[b] = a;
        }
    }
    std::unordered_map<std::uint32_t, std::uint32_t> chartOfRoot;
    std::vector<std::int64_t> vertexMap(mesh.positions.size(), -1);
    const double r = options.resolution;
    std::vector<glm::dvec2> lo, hi;
    std::vector<glm::dvec3> normalSum;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t root = find(mesh.indices[3 * t]);
        const auto [it, inserted] = chartOfRoot.emplace(root, std::uint32_t(atlas.charts.size()));
        if (inserted) {
            atlas.charts.emplace_back();
            lo.emplace_back(std::numeric_limits<double>::max());
            hi.emplace_back(-std::numeric_limits<double>::max());
            normalSum.emplace_back(0.0);
        }
        const std::uint32_t chart = it->second;
        const double area = triangleArea(mesh, t);
        atlas.charts[chart].area += area;
        atlas.charts[chart].triangles += 1;
        atlas.surfaceArea += area;
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
        normalSum[chart] += glm::cross(glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]) - a,
                glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]]) - a);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + k];
            if (vertexMap[v] < 0) {
                vertexMap[v] = std::int64_t(atlas.vertices.size());
                atlas.vertices.push_back({v, chart, mesh.texcoords1[v]});
            }
            atlas.indices.push_back(std::uint32_t(vertexMap[v]));
            lo[chart] = glm::min(lo[chart], glm::dvec2(mesh.texcoords1[v]) * r);
            hi[chart] = glm::max(hi[chart], glm::dvec2(mesh.texcoords1[v]) * r);
        }
    }
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        atlas.charts[c].origin = glm::ivec2(glm::floor(lo[c]));
        atlas.charts[c].size = glm::ivec2(glm::floor(hi[c])) + 1 - atlas.charts[c].origin;
        const double length = glm::length(normalSum[c]);
        atlas.charts[c].normal =
                length > 0.0 ? glm::vec3(normalSum[c] / length) : glm::vec3(0, 1, 0);
    }
    std::size_t covered = 0;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        rasterise(glm::dvec2(mesh.texcoords1[mesh.indices[3 * t]]) * r,
                glm::dvec2(mesh.texcoords1[mesh.indices[3 * t + 1]]) * r,
                glm::dvec2(mesh.texcoords1[mesh.indices[3 * t + 2]]) * r,
                [&](int, int) { ++covered; });
    }
    atlas.texelSize = covered > 0 ? std::sqrt(atlas.surfaceArea / double(covered)) : 0.0;
    atlas.fromTexcoord1 = true;
    return true;
}

} // namespace gi::atlas
