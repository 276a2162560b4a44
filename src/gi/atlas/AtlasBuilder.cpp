#include "gi/atlas/AtlasBuilder.h"

#include <stb_rect_pack.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace gi::atlas {
namespace {

constexpr double kSubTexel = 256.0; // fixed-point steps per texel of the rasteriser
// Limits that keep the rasteriser's 64-bit edge functions exact: vertices within 2^40 texels
// of the origin and triangles at most 2^22 texels wide (2^30 fixed-point steps), so every
// product of two coordinate differences stays below 2^62.
constexpr double kMaxRasterCoordinate = 1099511627776.0; // 2^40 texels
constexpr std::int64_t kMaxRasterExtent = std::int64_t(1) << 30;

// Texel-centre rasterisation in 24.8 fixed point (see forEachTexelCentre). False, visiting
// nothing, for a triangle outside the limits above.
template <class Visit> bool rasterise(glm::dvec2 fa, glm::dvec2 fb, glm::dvec2 fc, Visit&& visit) {
    for (const glm::dvec2& p : {fa, fb, fc}) {
        if (!(std::abs(p.x) < kMaxRasterCoordinate && std::abs(p.y) < kMaxRasterCoordinate)) {
            return false;
        }
    }
    auto snap = [](glm::dvec2 p) {
        return glm::i64vec2(std::llround(p.x * kSubTexel), std::llround(p.y * kSubTexel));
    };
    glm::i64vec2 a = snap(fa), b = snap(fb), c = snap(fc);
    const glm::i64vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    if (hi.x - lo.x > kMaxRasterExtent || hi.y - lo.y > kMaxRasterExtent) return false;
    const auto cross = [](glm::i64vec2 u, glm::i64vec2 v) { return u.x * v.y - u.y * v.x; };
    std::int64_t area = cross(b - a, c - a);
    if (area == 0) return true;
    if (area < 0) std::swap(b, c);
    const auto step = std::int64_t(kSubTexel);
    const auto half = step / 2;
    // Texels whose centre (i + 1/2) lies in [lo, hi].
    auto firstTexel = [&](std::int64_t v) {
        const std::int64_t t = v - half;
        return t >= 0 ? (t + step - 1) / step : -((-t) / step);
    };
    auto lastTexel = [&](std::int64_t v) {
        const std::int64_t t = v - half;
        return t >= 0 ? t / step : -((-t + step - 1) / step);
    };
    const std::int64_t x0 = firstTexel(lo.x), x1 = lastTexel(hi.x);
    const std::int64_t y0 = firstTexel(lo.y), y1 = lastTexel(hi.y);
    // A point on an edge belongs to the triangle for which the edge runs "downwards" (or
    // rightwards when horizontal); the neighbour across it traverses the edge the other way.
    auto owns = [](glm::i64vec2 d) { return d.y < 0 || (d.y == 0 && d.x > 0); };
    const glm::i64vec2 e0 = b - a, e1 = c - b, e2 = a - c;
    const bool o0 = owns(e0), o1 = owns(e1), o2 = owns(e2);
    const std::pair<glm::i64vec2, glm::i64vec2> edges[] = {{a, e0}, {b, e1}, {c, e2}};
    for (std::int64_t y = y0; y <= y1; ++y) {
        const std::int64_t py = y * step + half;
        // Each edge function is linear along the row, w(x0 + k) = w0 - e.y * step * k, so it
        // bounds k from one side; scanning only that span (widened by 2 for rounding) keeps a
        // long sliver from costing its whole bounding box. The exact test below decides.
        double first = 0.0, last = double(x1 - x0);
        for (const auto& [origin, e] : edges) {
            const std::int64_t w0 = cross(e, glm::i64vec2(x0 * step + half, py) - origin);
            if (e.y == 0) {
                if (w0 < 0) first = last + 1.0;
                continue;
            }
            const double root = double(w0) / double(e.y * step);
            if (e.y > 0) last = std::min(last, std::floor(root) + 2.0);
            else first = std::max(first, std::ceil(root) - 2.0);
        }
        if (first > last) continue;
        for (std::int64_t x = x0 + std::int64_t(first); x <= x0 + std::int64_t(last); ++x) {
            const glm::i64vec2 p(x * step + half, py);
            const std::int64_t w0 = cross(e0, p - a), w1 = cross(e1, p - b), w2 = cross(e2, p - c);
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            if ((w0 == 0 && !o0) || (w1 == 0 && !o1) || (w2 == 0 && !o2)) continue;
            visit(int(x), int(y));
        }
    }
    return true;
}

std::uint64_t cellKey(int x, int y) {
    return (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
}

// Occupied cells of one chart's projection, in 8x8 blocks of bits.
class Occupancy {
public:
    void clear() { mBlocks.clear(); }
    bool occupied(int x, int y) const {
        const auto it = mBlocks.find(cellKey(x >> 3, y >> 3));
        return it != mBlocks.end() && (it->second >> bit(x, y)) & 1u;
    }
    void mark(int x, int y) { mBlocks[cellKey(x >> 3, y >> 3)] |= std::uint64_t(1) << bit(x, y); }

private:
    static int bit(int x, int y) { return (y & 7) * 8 + (x & 7); }
    std::unordered_map<std::uint64_t, std::uint64_t> mBlocks;
};

struct Triangle {
    glm::dvec3 normal{0.0}; // unit, or zero when collapsed
    double area = 0.0;
};

glm::dvec3 tangentFor(const glm::dvec3& n) {
    const glm::dvec3 helper = std::abs(n.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    return glm::normalize(glm::cross(helper, n));
}

// Andrew's monotone chain; returns the hull counter-clockwise without repeating the start.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

// Rotation angle that gives the hull its minimum-area bounding rectangle (one hull edge lies
// on the rectangle, Freeman & Shapira 1975).
double minimumAreaAngle(const std::vector<glm::dvec2>& hull) {
    if (hull.size() < 3) {
        if (hull.size() == 2) return -std::atan2(hull[1].y - hull[0].y, hull[1].x - hull[0].x);
        return 0.0;
    }
    double best = std::numeric_limits<double>::max(), bestAngle = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 e = hull[(i + 1) % hull.size()] - hull[i];
        if (e.x == 0.0 && e.y == 0.0) continue;
        const double angle = -std::atan2(e.y, e.x);
        const double c = std::cos(angle), s = std::sin(angle);
        glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (const glm::dvec2& p : hull) {
            const glm::dvec2 r(c * p.x - s * p.y, s * p.x + c * p.y);
            lo = glm::min(lo, r);
            hi = glm::max(hi, r);
        }
        const double area = (hi.x - lo.x) * (hi.y - lo.y);
        if (area < best) {
            best = area;
            bestAngle = angle;
        }
    }
    return bestAngle;
}

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

Segmentation segment(const AtlasMesh& mesh, const std::vector<Triangle>& triangles,
        double gridScale, double cosLimit) {
    const std::size_t triangleCount = mesh.triangleCount();
    // Weld vertices by exact position so charts grow across attribute seams.
    std::vector<std::uint32_t> welded(mesh.positions.size());
    {
        struct Hash {
            std::size_t operator()(const glm::vec3& p) const {
                std::uint32_t bits[3];
                std::memcpy(bits, &p, sizeof bits);
                return std::size_t(bits[0] * 73856093u ^ bits[1] * 19349663u ^ bits[2] * 83492791u);
            }
        };
        std::unordered_map<glm::vec3, std::uint32_t, Hash> ids;
        ids.reserve(mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            welded[v] = ids.emplace(mesh.positions[v], std::uint32_t(ids.size())).first->second;
        }
    }
    // Triangles around each welded edge.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edges;
    edges.reserve(triangleCount * 2);
    auto edgeKey = [&](std::uint32_t a, std::uint32_t b) {
        a = welded[a];
        b = welded[b];
        if (a > b) std::swap(a, b);
        return (std::uint64_t(a) << 32) | b;
    };
    for (std::size_t t = 0; t < triangleCount; ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint64_t key =
                    edgeKey(mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
            if ((key >> 32) == (key & 0xffffffffu)) continue;
            edges[key].push_back(std::uint32_t(t));
        }
    }

    std::vector<std::uint32_t> order(triangleCount);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return triangles[a].area > triangles[b].area;
    });

    Segmentation result;
    std::vector<std::int32_t> chartOf(triangleCount, -1);
    Occupancy occupancy;
    std::vector<std::pair<int, int>> cells;
    for (const std::uint32_t seed : order) {
        if (chartOf[seed] >= 0) continue;
        const auto chartIndex = std::int32_t(result.charts.size());
        ChartLayout chart;
        glm::dvec3 n = triangles[seed].normal;
        if (n == glm::dvec3(0.0)) {
            const std::uint32_t* idx = &mesh.indices[3 * seed];
            n = glm::dvec3(mesh.normals[idx[0]] + mesh.normals[idx[1]] + mesh.normals[idx[2]]);
            n = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0, 1.0, 0.0);
        }
        chart.normal = n;
        const glm::dvec3 tu = tangentFor(n), tv = glm::cross(n, tu);
        auto project = [&](std::uint32_t vertex) {
            const glm::dvec3 p(mesh.positions[vertex]);
            return glm::dvec2(glm::dot(p, tu), glm::dot(p, tv));
        };
        // Adds t if its projection is free in the chart's occupancy grid (the seed always: a
        // triangle beyond the rasteriser's limits is only ever a chart of its own).
        auto tryAdd = [&](std::uint32_t t) {
            const std::uint32_t* idx = &mesh.indices[3 * t];
            cells.clear();
            const bool checked = rasterise(project(idx[0]) * gridScale,
                    project(idx[1]) * gridScale, project(idx[2]) * gridScale,
                    [&](int x, int y) { cells.emplace_back(x, y); });
            if (!checked && t != seed) return false;
            for (const auto& [x, y] : cells) {
                if (occupancy.occupied(x, y)) return false;
            }
            for (const auto& [x, y] : cells) occupancy.mark(x, y);
            chartOf[t] = chartIndex;
            chart.triangles.push_back(t);
            return true;
        };
        occupancy.clear();
        tryAdd(seed);
        std::queue<std::uint32_t> frontier;
        frontier.push(seed);
        while (!frontier.empty()) {
            const std::uint32_t t = frontier.front();
            frontier.pop();
            for (int e = 0; e < 3; ++e) {
                const std::uint64_t key =
                        edgeKey(mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
                const auto it = edges.find(key);
                if (it == edges.end()) continue;
                for (const std::uint32_t other : it->second) {
                    if (chartOf[other] >= 0) continue;
                    const Triangle& candidate = triangles[other];
                    const bool collapsed = candidate.normal == glm::dvec3(0.0);
                    if (!collapsed && glm::dot(candidate.normal, n) < cosLimit) continue;
                    if (tryAdd(other)) frontier.push(other);
                }
            }
        }
        // Project onto the seed plane and turn to the minimum-area bounding rectangle.
        std::vector<glm::dvec2> points;
        points.reserve(chart.triangles.size() * 3);
        for (const std::uint32_t t : chart.triangles) {
            for (int k = 0; k < 3; ++k) points.push_back(project(mesh.indices[3 * t + k]));
            chart.area += triangles[t].area;
        }
        const double angle = minimumAreaAngle(convexHull(points));
        const double c = std::cos(angle), s = std::sin(angle);
        glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (glm::dvec2& p : points) {
            p = glm::dvec2(c * p.x - s * p.y, s * p.x + c * p.y);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        for (glm::dvec2& p : points) p -= lo;
        chart.corners = std::move(points);
        chart.extent = hi - lo;
        result.charts.push_back(std::move(chart));
    }
    return result;
}

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

} // namespace

void forEachTexelCentre(
        glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, const std::function<void(int, int)>& visit) {
    rasterise(a, b, c, visit);
}

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

bool buildAtlas(
        const AtlasMesh& mesh, const AtlasOptions& options, Atlas& atlas, std::string& error) {
    atlas = Atlas{};
    atlas.resolution = options.resolution;
    atlas.gutter = options.gutter;
    const std::size_t triangleCount = mesh.triangleCount();
    if (triangleCount == 0) {
        error = "the scene has no triangles to place in the atlas";
        return false;
    }
    std::string why;
    if (options.useTexcoord1 && texcoord1IsAtlas(mesh, options.resolution, why)) {
        return buildFromTexcoord1(mesh, options, atlas);
    }

    std::vector<Triangle> triangles(triangleCount);
    double totalArea = 0.0, longestEdge = 0.0;
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
    // Bisection on the density between a failing upper bound and a fitting lower one.
    std::vector<glm::ivec2> origins, best;
    double high = densityBound, low = 0.0, density = 0.85 * densityBound;
    for (int attempt = 0; attempt < 60 && low == 0.0; ++attempt) {
        if (pack(charts, density, padding, options.resolution, origins)) {
            low = density;
            best = origins;
        } else {
            high = density;
            density *= 0.85;
        }
    }
    if (low == 0.0) {
        error = "could not pack " + std::to_string(charts.size()) + " charts into a " +
                std::to_string(options.resolution) + "^2 atlas";
        return false;
    }
    for (int step = 0; step < 7; ++step) {
        const double middle = 0.5 * (low + high);
        if (pack(charts, middle, padding, options.resolution, origins)) {
            low = middle;
            best = origins;
        } else {
            high = middle;
        }
    }
    density = low;
    atlas.texelSize = 1.0 / density;

    std::unordered_map<std::uint64_t, std::uint32_t> vertexOf;
    vertexOf.reserve(mesh.positions.size() * 2);
    atlas.indices.assign(triangleCount * 3, 0);
    atlas.charts.resize(charts.size());
    for (std::size_t c = 0; c < charts.size(); ++c) {
        const ChartLayout& layout = charts[c];
        AtlasChart& chart = atlas.charts[c];
        chart.origin = best[c];
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
    return true;
}

} // namespace gi::atlas
