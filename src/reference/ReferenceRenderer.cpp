#include "reference/ReferenceRenderer.h"

#include "reference/EmbreeScene.h"
#include "reference/OwenSobol.h"
#include "reference/PathTracer.h"
#include "reference/Pcg32.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace gi::reference {

namespace {

constexpr int kTileSize = 16;

// Per-pixel half means, kept until the noise estimate is computed.
struct HalfImages {
    std::vector<glm::vec3> direct[2];
    std::vector<glm::vec3> indirect[2];
};

// One pixel's estimate: the mean radiance of each half of its paths.
struct PixelEstimate {
    glm::dvec3 direct[2];
    glm::dvec3 indirect[2];
    int hits = 0;   // paths whose camera ray hit geometry
};

// Traces pathsPerHalf[h] paths for each half h of pixel (x, y). Half h draws from its own
// streams seeded by (seed, pixel, h): Owen-scrambled Sobol' points for the pixel position,
// first bounce and first light, PCG32 for everything else. With `centre` every path leaves
// through the pixel's centre and the position's two dimensions go unused.
PixelEstimate renderPixel(const PathTracer& tracer, int x, int y, std::uint64_t seed,
        std::size_t pixel, const int pathsPerHalf[2], bool centre,
        std::vector<LightVertex>& lightVertices, RayCounts& rays) {
    PixelEstimate estimate;
    const std::uint64_t stream = mix64(seed ^ std::uint64_t(pixel));
    for (int h = 0; h < 2; ++h) {
        Pcg32 rng(stream, std::uint64_t(h));
        const OwenSobolSampler sampler(std::uint32_t(mix64(stream + std::uint64_t(h))));
        glm::dvec3 direct(0.0), indirect(0.0);
        for (int s = 0; s < pathsPerHalf[h]; ++s) {
            float u[kSobolDimensions];
            sampler.point(std::uint32_t(s), u);
            const float px = centre ? 0.5f : u[0];
            const float py = centre ? 0.5f : u[1];
            const PathSample path =
                    tracer.trace(float(x) + px, float(y) + py, u + 2, rng, lightVertices, rays);
            direct += glm::dvec3(path.direct);
            indirect += glm::dvec3(path.indirect);
            estimate.hits += path.hit ? 1 : 0;
        }
        const double n = double(std::max(pathsPerHalf[h], 1));
        estimate.direct[h] = direct / n;
        estimate.indirect[h] = indirect / n;
    }
    return estimate;
}

// What the tiles of one render() call share.
struct RenderJob {
    const PathTracer& tracer;
    int width;
    int spp;
    std::uint64_t seed;
    int pathsPerHalf[2];
    bool pixelCentre;
    ReferenceResult& result;
    HalfImages& halves;
};

// Renders the pixels [x0, x1) x [y0, y1) into the job's images.
void renderTile(const RenderJob& job, int x0, int y0, int x1, int y1,
        std::vector<LightVertex>& lightVertices, RayCounts& rays) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(job.width) + std::size_t(x);
            const PixelEstimate e = renderPixel(job.tracer, x, y, job.seed, pixel,
                    job.pathsPerHalf, job.pixelCentre, lightVertices, rays);
            const double wA = double(job.pathsPerHalf[0]) / job.spp;
            const double wB = double(job.pathsPerHalf[1]) / job.spp;
            const glm::dvec3 direct = wA * e.direct[0] + wB * e.direct[1];
            const glm::dvec3 indirect = wA * e.indirect[0] + wB * e.indirect[1];
            job.result.direct.set(x, y, glm::vec3(direct));
            job.result.indirect.set(x, y, glm::vec3(indirect));
            job.result.final.set(x, y, glm::vec3(direct + indirect));
            job.result.coverage[pixel] = float(double(e.hits) / double(job.spp));
            for (int h = 0; h < 2; ++h) {
                job.halves.direct[h][pixel] = glm::vec3(e.direct[h]);
                job.halves.indirect[h][pixel] = glm::vec3(e.indirect[h]);
            }
        }
    }
}

double relativeNoise(const HalfImages& halves, const core::Image& combined,
        const std::vector<float>& coverage, bool directPart, bool indirectPart, int spp) {
    if (spp < 2) return std::numeric_limits<double>::quiet_NaN();
    const double nA = double((spp + 1) / 2), nB = double(spp / 2);
    const double factor = nA * nB / (double(spp) * double(spp));
    double difference = 0.0, energy = 0.0;
    std::size_t pixels = 0;
    for (std::size_t p = 0; p < coverage.size(); ++p) {
        if (!(coverage[p] > kGeometryCoverage)) continue;
        ++pixels;
        glm::dvec3 a(0.0), b(0.0);
        if (directPart) {
            a += glm::dvec3(halves.direct[0][p]);
            b += glm::dvec3(halves.direct[1][p]);
        }
        if (indirectPart) {
            a += glm::dvec3(halves.indirect[0][p]);
            b += glm::dvec3(halves.indirect[1][p]);
        }
        const glm::dvec3 d = a - b;
        difference += glm::dot(d, d);
        const glm::dvec3 c(combined.rgb[3 * p], combined.rgb[3 * p + 1], combined.rgb[3 * p + 2]);
        energy += glm::dot(c, c);
    }
    if (pixels == 0) return std::numeric_limits<double>::quiet_NaN();
    if (energy <= 0.0) return difference <= 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return std::sqrt(difference * factor / energy);
}

} // namespace

ReferenceRenderer::ReferenceRenderer(const scene::Scene& scene) : mScene(scene) {
    mState = buildEmbreeState(scene, mError);
}

ReferenceRenderer::~ReferenceRenderer() = default;

bool ReferenceRenderer::valid() const { return mState != nullptr; }

double ReferenceRenderer::buildSeconds() const { return mState ? mState->buildSeconds : 0.0; }

ReferenceResult ReferenceRenderer::render(const scene::CameraView& camera, int width, int height,
        const ReferenceSettings& settings, const ProgressCallback& progress) const {
    ReferenceResult result;
    if (!mState || width <= 0 || height <= 0) return result;
    const auto start = std::chrono::steady_clock::now();
    const int spp = std::max(settings.spp, 1);
    const int bounces = std::max(settings.bounces, 0);
    const std::size_t pixelCount = std::size_t(width) * std::size_t(height);
    result.direct = core::Image(width, height);
    result.indirect = core::Image(width, height);
    result.final = core::Image(width, height);
    result.coverage.assign(pixelCount, 0.0f);
    result.spp = spp;
    result.bounces = bounces;

    HalfImages halves;
    for (int h = 0; h < 2; ++h) {
        halves.direct[h].assign(pixelCount, glm::vec3(0.0f));
        halves.indirect[h].assign(pixelCount, glm::vec3(0.0f));
    }

    const PathTracer tracer(*mState, mScene.lights, camera, width, height, bounces,
            settings.glossy);
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    const std::uint64_t seed = mix64(std::uint64_t(std::uint32_t(settings.seed)));
    const RenderJob job{tracer, width, spp, seed, {(spp + 1) / 2, spp / 2},
            settings.pixel == kReferencePixelCentre, result, halves};

    std::atomic<int> nextTile{0};
    std::mutex progressMutex;
    std::size_t pixelsDone = 0;
    double lastReported = -1.0;
    RayCounts totalRays;

    auto worker = [&] {
        RayCounts rays;
        std::vector<LightVertex> lightVertices;
        for (int tile = nextTile++; tile < tileCount; tile = nextTile++) {
            const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
            renderTile(job, x0, y0, x1, y1, lightVertices, rays);
            const std::lock_guard<std::mutex> lock(progressMutex);
            pixelsDone += std::size_t(x1 - x0) * std::size_t(y1 - y0);
            const double fraction = double(pixelsDone) / double(pixelCount);
            if (progress && fraction < 1.0 && fraction > lastReported) {
                lastReported = fraction;
                progress(fraction);
            }
        }
        const std::lock_guard<std::mutex> lock(progressMutex);
        totalRays.primary += rays.primary;
        totalRays.shadow += rays.shadow;
        totalRays.bounce += rays.bounce;
        totalRays.light += rays.light;
    };

    int threads = settings.threads > 0 ? settings.threads
                                       : int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::clamp(threads, 1, tileCount);
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
    if (progress) progress(1.0);

    result.rays = totalRays;
    result.noise.direct = relativeNoise(halves, result.direct, result.coverage, true, false, spp);
    result.noise.indirect =
            relativeNoise(halves, result.indirect, result.coverage, false, true, spp);
    result.noise.final = relativeNoise(halves, result.final, result.coverage, true, true, spp);
    result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

ReferenceResult renderReference(const scene::Scene& scene, const scene::CameraView& camera,
        int width, int height, const ReferenceSettings& settings,
        const ProgressCallback& progress) {
    const ReferenceRenderer renderer(scene);
    return renderer.render(camera, width, height, settings, progress);
}

} // namespace gi::reference
