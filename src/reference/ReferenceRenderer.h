// Ground-truth renderer: a CPU path tracer over Embree 3 that solves the radiometry of
// DESIGN.md exactly (up to Monte Carlo noise), for scoring the voxel and atlas GI modes.
// - Surfaces are Lambertian, f = rho/pi, rho = baseColorFactor x base-colour texture (sRGB
//   decoded, bilinear, with the sampler's wrap modes) x COLOR_0; emission Le = emissiveFactor x
//   emissive texture, from the front side (both sides when doubleSided). alphaMode MASK
//   cut-outs are Embree filter functions. With ReferenceSettings::glossy (material.model=gltf)
//   every surface has the glTF metallic-roughness BRDF instead (GltfBrdf.h), sampled by its
//   own lobes; PathTracer.h says what changes.
// - Punctual lights by next-event estimation with shadow rays: E = I cos(theta)/d^2 (point),
//   x s^2 (spot), E = I cos(theta) (directional); glTF `range` is never applied.
// - Area lights (emissive surfaces, command-line rectangles) by next-event estimation too: a
//   point picked over all their triangles in proportion to power, with a shadow ray, combined
//   by multiple importance sampling with the cosine rays that hit the same triangles. The sky
//   (constant radiance L) by the cosine rays that escape: an open plane shows rho L.
// - Indirect light by cosine-weighted hemisphere sampling (pdf = cos/pi, so the throughput is
//   multiplied by rho), for exactly `bounces` bounces and no Russian roulette: with bounces = 1
//   the secondary hit adds its direct light from every kind of light, i.e. every light reaches
//   the image after at most bounces + 1 scatterings (PBRT 3rd ed. 14.5 "path tracing", 13.6.3
//   cosine-weighted hemisphere sampling). Light that point and spot lights send to later
//   vertices is also sampled from the light (a one-vertex light subpath joined to the path),
//   and both estimates are combined by multiple importance sampling (Veach 1997 ch. 9): a
//   light close to a wall then does not turn into fireflies in the indirect image.
//   PathTracer.h has the estimators in full.
// - A pixel is the mean radiance over its square: paths start at stratified positions over
//   the whole pixel (Owen-scrambled Sobol', see OwenSobol.h, which also stratifies the first
//   bounce and the first light's emission). Each pixel's numbers are seeded from (seed, pixel
//   index), so images are bit-identical for any thread count.
// - Ray origins are offset along the geometric normal by a distance relative to the magnitude
//   of the triangle's coordinates, so scenes at any scale (mm or km) avoid self-intersection.
#pragma once

#include "reference/ImageMetrics.h"
#include "scene/CameraView.h"
#include "core/Image.h"
#include "core/Settings.h"
#include "scene/Scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gi::reference {

// Called with the finished fraction in [0, 1], non-decreasing, from one thread at a time
// (not necessarily the caller's). The last call is with 1.
using ProgressCallback = std::function<void(double fraction)>;

struct RayCounts {
    std::uint64_t primary = 0;   // camera rays
    std::uint64_t shadow = 0;    // visibility rays: towards punctual lights and points of
                                 // area lights (next-event estimation) and between a path
                                 // and a light vertex
    std::uint64_t bounce = 0;    // rays sampled from the BRDF (continuations, and the last
                                 // vertex's closing ray in scenes with emission or a sky)
    std::uint64_t light = 0;     // rays sampled from a light's emission (light vertices)
    std::uint64_t total() const { return primary + shadow + bounce + light; }
};

// Estimated relative noise of the combined (all-spp) image over geometry pixels (coverage >
// kGeometryCoverage): the RMS of its Monte Carlo error over the RMS of its values,
// sqrt(sum sigma^2 / sum C^2) over pixels and RGB. Derivation: each pixel's paths form two
// independent halves A and B (nA = ceil(spp/2) and nB = floor(spp/2) paths, each half from its
// own random stream, as if rendered with two seeds); the image is C = (nA A + nB B) / spp.
// With per-path variance s^2, Var(A - B) = s^2 (1/nA + 1/nB) and Var(C) = s^2 / spp, so
//     Var(C) = Var(A - B) nA nB / spp^2            (= Var(A - B) / 4 when nA = nB),
// and (A - B)^2 estimates Var(A - B) without bias. Hence
//     noise(C) = sqrt(sum (A - B)^2 nA nB / spp^2) / sqrt(sum C^2),
// which for even spp is RMSE(A, B) / 2 relative to C: A - B has sqrt(2) times the noise of a
// half, and C has 1/sqrt(2) of it. For even spp this needs only that A and B are independent
// and identically distributed, so it holds for the stratified samples used here; for odd spp
// it assumes a half's variance falls as 1/n. NaN when spp < 2 or there is no geometry pixel;
// 0 when the component is zero on every geometry pixel (e.g. no indirect light).
struct NoiseEstimate {
    double direct = 0.0;
    double indirect = 0.0;
    double final = 0.0;
};

struct ReferenceResult {
    core::Image direct;        // linear radiance: emission seen directly + direct light at
                                 // the first hit (from every light, emissive surfaces and
                                 // the sky included)
    core::Image indirect;      // everything after the first surface's direct light:
                                 // final - direct
    core::Image final;         // direct + indirect
    std::vector<float> coverage; // width * height, rows top to bottom: fraction of the pixel's
                                 // paths whose camera ray hit geometry, in [0, 1]
    NoiseEstimate noise;
    RayCounts rays;
    double seconds = 0.0;        // wall-clock time of the render (not of the scene build)
    int spp = 0, bounces = 0;

    int width() const { return final.width; }
    int height() const { return final.height; }
    double raysPerSecond() const { return seconds > 0.0 ? double(rays.total()) / seconds : 0.0; }
};

struct EmbreeState;

// Builds the Embree scene once (world-space triangles of every instance); render() may then be
// called any number of times, also concurrently. The Scene must outlive the renderer: its
// textures are sampled, and its lights are read by every render() call (so lights added after
// construction, e.g. from the command line, are used; geometry and materials are not re-read).
class ReferenceRenderer {
public:
    explicit ReferenceRenderer(const scene::Scene& scene);
    ~ReferenceRenderer();
    ReferenceRenderer(const ReferenceRenderer&) = delete;
    ReferenceRenderer& operator=(const ReferenceRenderer&) = delete;

    // False when Embree could not be initialised; error() says why. render() then returns an
    // empty result.
    bool valid() const;
    const std::string& error() const { return mError; }
    double buildSeconds() const;   // wall-clock time of the Embree scene build

    // Renders width x height pixels seen from `camera` (its projection and view; the aspect
    // ratio is the caller's, normally width / height). settings.threads = 0 uses all cores.
    [[nodiscard]] ReferenceResult render(const scene::CameraView& camera, int width, int height,
            const ReferenceSettings& settings, const ProgressCallback& progress = {}) const;

private:
    const scene::Scene& mScene;
    std::unique_ptr<EmbreeState> mState;
    std::string mError;
};

// Convenience for one image: builds a renderer for `scene` and renders.
[[nodiscard]] ReferenceResult renderReference(const scene::Scene& scene,
        const scene::CameraView& camera, int width, int height,
        const ReferenceSettings& settings, const ProgressCallback& progress = {});

} // namespace gi::reference
