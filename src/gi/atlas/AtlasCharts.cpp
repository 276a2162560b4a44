#include "gi/atlas/AtlasCharts.h"

#include "gi/atlas/TexelRasteriser.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace gi::atlas {
namespace {

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

// Triangles around each edge, with vertices welded by exact position so charts grow across
// attribute seams.
class EdgeAdjacency {
public:
    explicit EdgeAdjacency(const AtlasMesh& mesh) : mWelded(mesh.positions.size()) {
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
            mWelded[v] = ids.emplace(mesh.positions[v], std::uint32_t(ids.size())).first->second;
        }
        const std::size_t triangleCount = mesh.triangleCount();
        mEdges.reserve(triangleCount * 2);
        for (std::size_t t = 0; t < triangleCount; ++t) {
            for (int e = 0; e < 3; ++e) {
                const std::uint64_t key =
                        edgeKey(mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
                if ((key >> 32) == (key & 0xffffffffu)) continue;
                mEdges[key].push_back(std::uint32_t(t));
            }
        }
    }

    // Triangles on the edge between mesh vertices a and b; null when there are none.
    const std::vector<std::uint32_t>* around(std::uint32_t a, std::uint32_t b) const {
        const auto it = mEdges.find(edgeKey(a, b));
        return it == mEdges.end() ? nullptr : &it->second;
    }

private:
    std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) const {
        a = mWelded[a];
        b = mWelded[b];
        if (a > b) std::swap(a, b);
        return (std::uint64_t(a) << 32) | b;
    }

    std::vector<std::uint32_t> mWelded;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> mEdges;
};

// Grows one chart at a time from a seed triangle; which triangles are taken persists between
// charts.
class ChartGrower {
public:
    ChartGrower(const AtlasMesh& mesh, const std::vector<Triangle>& triangles, double gridScale,
            double cosLimit)
        : mMesh(mesh), mTriangles(triangles), mAdjacency(mesh), mGridScale(gridScale),
          mCosLimit(cosLimit), mChartOf(mesh.triangleCount(), -1) {}

    bool assigned(std::uint32_t t) const { return mChartOf[t] >= 0; }

    ChartLayout grow(std::uint32_t seed, std::int32_t chartIndex) {
        const AtlasMesh& mesh = mMesh;
        ChartLayout chart;
        glm::dvec3 n = mTriangles[seed].normal;
        if (n == glm::dvec3(0.0)) {
            const std::uint32_t* idx = &mesh.indices[3 * seed];
            n = glm::dvec3(mesh.normals[idx[0]] + mesh.normals[idx[1]] + mesh.normals[idx[2]]);
            n = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0, 1.0, 0.0);
        }
        chart.normal = n;
        mTu = tangentFor(n);
        mTv = glm::cross(n, mTu);
        mOccupancy.clear();
        tryAdd(seed, seed, chartIndex, chart);
        std::queue<std::uint32_t> frontier;
        frontier.push(seed);
        while (!frontier.empty()) {
            const std::uint32_t t = frontier.front();
            frontier.pop();
            for (int e = 0; e < 3; ++e) {
                const std::vector<std::uint32_t>* others = mAdjacency.around(
                        mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
                if (others == nullptr) continue;
                for (const std::uint32_t other : *others) {
                    if (mChartOf[other] >= 0) continue;
                    const Triangle& candidate = mTriangles[other];
                    const bool collapsed = candidate.normal == glm::dvec3(0.0);
                    if (!collapsed && glm::dot(candidate.normal, n) < mCosLimit) continue;
                    if (tryAdd(other, seed, chartIndex, chart)) frontier.push(other);
                }
            }
        }
        fitRectangle(chart);
        return chart;
    }

private:
    glm::dvec2 project(std::uint32_t vertex) const {
        const glm::dvec3 p(mMesh.positions[vertex]);
        return glm::dvec2(glm::dot(p, mTu), glm::dot(p, mTv));
    }

    // Adds t if its projection is free in the chart's occupancy grid (the seed always: a
    // triangle beyond the rasteriser's limits is only ever a chart of its own).
    bool tryAdd(std::uint32_t t, std::uint32_t seed, std::int32_t chartIndex, ChartLayout& chart) {
        const std::uint32_t* idx = &mMesh.indices[3 * t];
        mCells.clear();
        const bool checked = rasterise(project(idx[0]) * mGridScale,
                project(idx[1]) * mGridScale, project(idx[2]) * mGridScale,
                [&](int x, int y) { mCells.emplace_back(x, y); });
        if (!checked && t != seed) return false;
        for (const auto& [x, y] : mCells) {
            if (mOccupancy.occupied(x, y)) return false;
        }
        for (const auto& [x, y] : mCells) mOccupancy.mark(x, y);
        mChartOf[t] = chartIndex;
        chart.triangles.push_back(t);
        return true;
    }

    // Projects onto the seed plane and turns to the minimum-area bounding rectangle.
    void fitRectangle(ChartLayout& chart) const {
        std::vector<glm::dvec2> points;
        points.reserve(chart.triangles.size() * 3);
        for (const std::uint32_t t : chart.triangles) {
            for (int k = 0; k < 3; ++k) points.push_back(project(mMesh.indices[3 * t + k]));
            chart.area += mTriangles[t].area;
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
    }

    const AtlasMesh& mMesh;
    const std::vector<Triangle>& mTriangles;
    const EdgeAdjacency mAdjacency;
    const double mGridScale;
    const double mCosLimit;
    std::vector<std::int32_t> mChartOf;
    Occupancy mOccupancy;
    std::vector<std::pair<int, int>> mCells;
    glm::dvec3 mTu{0.0}, mTv{0.0}; // the current chart's projection axes
};

} // namespace

Segmentation segment(const AtlasMesh& mesh, const std::vector<Triangle>& triangles,
        double gridScale, double cosLimit) {
    ChartGrower grower(mesh, triangles, gridScale, cosLimit);
    std::vector<std::uint32_t> order(mesh.triangleCount());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return triangles[a].area > triangles[b].area;
    });
    Segmentation result;
    for (const std::uint32_t seed : order) {
        if (grower.assigned(seed)) continue;
        const auto chartIndex = std::int32_t(result.charts.size());
        result.charts.push_back(grower.grow(seed, chartIndex));
    }
    return result;
}

} // namespace gi::atlas
