#include "gi/atlas/SurfacePoints.h"

#include <algorithm>
#include <cmath>

namespace gi::atlas {

SurfacePoints surfacePoints(const AtlasMesh& mesh, int count) {
    SurfacePoints out;
    const std::size_t triangles = mesh.triangleCount();
    std::vector<double> prefix(triangles);
    double total = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const double area = triangleArea(mesh, t);
        total += std::isfinite(area) ? area : 0.0;
        prefix[t] = total;
    }
    if (count <= 0 || !(total > 0.0)) return out;
    out.areaPerPoint = total / double(count);
    constexpr double kGolden = 0.6180339887498949;
    out.points.reserve(std::size_t(count));
    for (int k = 0; k < count; ++k) {
        const double target = (double(k) + 0.5) / double(count) * total;
        const auto it = std::upper_bound(prefix.begin(), prefix.end(), target);
        const std::size_t t = std::min(std::size_t(it - prefix.begin()), triangles - 1);
        const double start = t > 0 ? prefix[t - 1] : 0.0;
        const double area = prefix[t] - start;
        const double along = area > 0.0 ? std::clamp((target - start) / area, 0.0, 1.0) : 0.5;
        const double across = std::fmod((double(k) + 0.5) * kGolden, 1.0);
        const double s = std::sqrt(along);
        SurfacePoint p{};
        for (int i = 0; i < 3; ++i) p.vertex[i] = mesh.indices[3 * t + std::size_t(i)];
        p.doubleSided = mesh.doubleSided.empty() ? 0u : mesh.doubleSided[p.vertex[0]];
        p.b1 = float(s * (1.0 - across));
        p.b2 = float(s * across);
        out.points.push_back(p);
    }
    return out;
}

} // namespace gi::atlas
