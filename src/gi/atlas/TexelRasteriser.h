// Exact texel-centre rasterisation shared by atlas building and checking: vertices snapped to
// 1/256 texel and edge functions evaluated in 64-bit integers with a consistent tie rule, so two
// triangles sharing an edge never both claim a texel centre and never both miss one.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace gi::atlas {

inline constexpr double kSubTexel = 256.0; // fixed-point steps per texel of the rasteriser

// Limits that keep the rasteriser's 64-bit edge functions exact: vertices within 2^40 texels
// of the origin and triangles at most 2^22 texels wide (2^30 fixed-point steps), so every
// product of two coordinate differences stays below 2^62.
inline constexpr double kMaxRasterCoordinate = 1099511627776.0; // 2^40 texels
inline constexpr std::int64_t kMaxRasterExtent = std::int64_t(1) << 30;

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

} // namespace gi::atlas
