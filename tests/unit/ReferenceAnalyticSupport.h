// Shared by the reference-renderer physics tests (Reference*Test.cpp): render settings in one
// call, Lambert's polygon irradiance, the noise of two renders and the noise line each test
// prints so a run shows how converged it was, and the mean of a field over a pixel's
// footprint on the ground plane.
#pragma once

#include "ReferenceTestScenes.h"
#include "reference/ReferenceRenderer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace gi::test {

inline ReferenceSettings referenceSettings(
        int spp, int bounces, int seed = 1, int threads = 0) {
    ReferenceSettings settings;
    settings.spp = spp;
    settings.bounces = bounces;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

// Irradiance at x (unit normal n) from a uniformly emitting polygon of radiance le, by
// Lambert's formula E = le/2 |sum_i theta_i n . (r_i x r_(i+1)) / |r_i x r_(i+1)||, r_i the
// unit vectors from x to the corners, theta_i the angle between r_i and r_(i+1). Exact for a
// polygon wholly above the tangent plane.
inline double polygonIrradiance(const glm::dvec3& x, const glm::dvec3& n,
        const std::vector<glm::dvec3>& polygon, double le) {
    double sum = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 a = glm::normalize(polygon[i] - x);
        const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - x);
        const glm::dvec3 c = glm::cross(a, b);
        const double length = glm::length(c);
        if (length <= 0.0) continue;
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, c / length);
    }
    return 0.5 * le * std::abs(sum);
}

// Relative noise of one of two renders a and b of a scene (equal spp, other seeds) over the
// pixels use(x, y) selects: RMS(a - b) / sqrt(2) over RMS((a + b) / 2), over all channels.
// The mean (a + b) / 2 has 1/sqrt(2) of it.
template <class Use>
double twoSeedNoise(const core::Image& a, const core::Image& b, Use use) {
    double difference = 0.0, energy = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            if (!use(x, y)) continue;
            const glm::dvec3 d = glm::dvec3(a.at(x, y)) - glm::dvec3(b.at(x, y));
            const glm::dvec3 c = 0.5 * (glm::dvec3(a.at(x, y)) + glm::dvec3(b.at(x, y)));
            difference += 0.5 * glm::dot(d, d);
            energy += glm::dot(c, c);
        }
    }
    return energy > 0.0 ? std::sqrt(difference / energy) : 0.0;
}

inline void printNoise(const char* what, const reference::ReferenceResult& result) {
    std::printf("[ noise    ] %s: %dx%d, %d spp, %d bounces: relative noise direct %.3g%%, "
                "indirect %.3g%%, final %.3g%%; %.2f s, %.2f Mrays/s\n",
            what, result.width(), result.height(), result.spp, result.bounces,
            100.0 * result.noise.direct, 100.0 * result.noise.indirect,
            100.0 * result.noise.final, result.seconds, result.raysPerSecond() * 1e-6);
}

// Mean of f over the pixel's footprint on the plane y = 0 (n x n sub-positions); false when a
// sub-position misses the square |x|, |z| <= halfSize.
template <class F>
bool footprintMean(const scene::CameraView& camera, int width, int height, int px, int py,
        double halfSize, int n, F f, double& mean) {
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const PixelRay ray = pixelRay(camera, width, height, px + (i + 0.5) / n,
                    py + (j + 0.5) / n);
            glm::dvec3 p;
            if (ray.direction.y >= 0.0 || !hitPlaneY(ray, 0.0, p) ||
                    std::abs(p.x) > halfSize || std::abs(p.z) > halfSize) {
                return false;
            }
            sum += f(p);
        }
    }
    mean = sum / double(n * n);
    return true;
}

} // namespace gi::test
