// Shared by the reference-renderer physics tests (ReferenceAnalytic*Test.cpp): render settings
// in one call, the noise line each test prints so a run shows how converged it was, and the
// mean of a field over a pixel's footprint on the ground plane.
#pragma once

#include "ReferenceTestScenes.h"
#include "reference/ReferenceRenderer.h"

#include <cmath>
#include <cstdio>

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
