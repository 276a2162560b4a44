// Physics tests of the ground-truth renderer against closed-form radiance (DESIGN.md
// "Testing": analytic scenes that cannot drift with a re-baselined image):
// - a plane under a point, spot and directional light: L = rho/pi x E with E from
//   "Radiometric conventions", averaged over each pixel's footprint;
// - a closed emitting box: L = Le (1 - rho^(k+1)) / (1 - rho) after k bounces, also with the
//   scene scaled by 1e-3 and 1e4 (ray offsets must follow the scale);
// - a square emitter over a receiver: one-bounce L = rho/pi x E, E from Lambert's polygon
//   formula (Arvo, "Applications of Irradiance Tensors...", SIGGRAPH 1995);
// - alpha-mask cut-outs in camera and shadow rays, sRGB texture decoding;
// - determinism across thread counts.
#include "ReferenceTestScenes.h"
#include "core/Colour.h"
#include "reference/ReferenceRenderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace gi::reference {
namespace {

using test::PixelRay;
using test::pixelRay;

ReferenceSettings referenceSettings(int spp, int bounces, int seed = 1, int threads = 0) {
    ReferenceSettings settings;
    settings.spp = spp;
    settings.bounces = bounces;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

void printNoise(const char* what, const ReferenceResult& result) {
    std::printf("[ noise    ] %s: %dx%d, %d spp, %d bounces: relative noise direct %.3g%%, "
                "indirect %.3g%%, final %.3g%%; %.2f s, %.2f Mrays/s\n",
            what, result.width(), result.height(), result.spp, result.bounces,
            100.0 * result.noise.direct, 100.0 * result.noise.indirect,
            100.0 * result.noise.final, result.seconds, result.raysPerSecond() * 1e-6);
}

scene::Scene loadPlaneScene() {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    const std::string path =
            std::string(VOXATLAS_DATA_DIR) + "/assets/analytic/plane_point_light.gltf";
    EXPECT_TRUE(scene::loadGltf(path, scene, error, warnings)) << error;
    return scene;
}

// Irradiance E at `x` (surface normal n) from light `light`, unshadowed (DESIGN.md).
double punctualIrradiance(const scene::Light& light, const glm::dvec3& x, const glm::dvec3& n) {
    const double intensity = double(light.intensity);
    if (light.type == scene::LightType::Directional) {
        return intensity * std::max(0.0, glm::dot(n, -glm::normalize(glm::dvec3(light.direction))));
    }
    const glm::dvec3 toLight = glm::dvec3(light.position) - x;
    const double d2 = glm::dot(toLight, toLight);
    const glm::dvec3 wi = toLight / std::sqrt(d2);
    double e = intensity * std::max(0.0, glm::dot(n, wi)) / d2;
    if (light.type == scene::LightType::Spot) {
        const double cosAlpha = glm::dot(glm::normalize(glm::dvec3(light.direction)), -wi);
        const double cosOuter = std::cos(double(light.outerConeAngle));
        const double cosInner = std::cos(double(light.innerConeAngle));
        const double s = std::clamp((cosAlpha - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
        e *= s * s;
    }
    return e;
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
            if (ray.direction.y >= 0.0 || !test::hitPlaneY(ray, 0.0, p) ||
                    std::abs(p.x) > halfSize || std::abs(p.z) > halfSize) {
                return false;
            }
            sum += f(p);
        }
    }
    mean = sum / double(n * n);
    return true;
}

// Renders the plane of plane_point_light.gltf (rho = 0.5, 2 m square at y = 0) under `light`
// and compares every fully covered pixel with rho/pi x E averaged over its footprint. With
// `scale`, scene, camera and light position are scaled and point/spot intensities multiplied
// by scale^2, which leaves the image unchanged.
void expectPlaneMatches(scene::Light light, double minimumRadiance, float scale = 1.0f) {
    scene::Scene scene = loadPlaneScene();
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_FALSE(scene.cameras.empty());
    light.position *= scale;
    if (light.type != scene::LightType::Directional) light.intensity *= scale * scale;
    scene.lights[0] = light;
    for (scene::Instance& instance : scene.instances) {
        instance.worldFromLocal = glm::scale(glm::mat4(1.0f), glm::vec3(scale)) *
                                  instance.worldFromLocal;
    }
    scene.bounds.min *= scale;
    scene.bounds.max *= scale;
    glm::vec4& eye = scene.cameras[0].worldFromCamera[3];
    eye = glm::vec4(glm::vec3(eye) * scale, 1.0f);
    scene.cameras[0].znear *= scale;
    scene.cameras[0].zfar *= scale;
    constexpr int kWidth = 64, kHeight = 48;
    const scene::CameraView camera =
            scene::cameraFromScene(scene.cameras[0], float(kWidth) / kHeight, scene.bounds);
    // 64 paths per pixel: direct light has no Monte Carlo noise except the jitter over the
    // pixel, whose effect on the pixel mean is ~0.1 % where the field is steepest.
    const ReferenceResult result =
            renderReference(scene, camera, kWidth, kHeight, referenceSettings(64, 1));
    ASSERT_EQ(result.width(), kWidth);
    printNoise("plane", result);
    const double rho = double(scene.materials[0].baseColorFactor.r);

    int probes = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            double expected = 0.0;
            // 16 x 16 sub-positions integrate the smooth field over the pixel to ~1e-5.
            if (!footprintMean(camera, kWidth, kHeight, x, y, 0.999 * scale, 16,
                        [&](const glm::dvec3& p) {
                            return rho / glm::pi<double>() *
                                   punctualIrradiance(light, p, glm::dvec3(0.0, 1.0, 0.0));
                        },
                        expected)) {
                continue;
            }
            EXPECT_FLOAT_EQ(result.coverage[std::size_t(y) * kWidth + std::size_t(x)], 1.0f);
            EXPECT_EQ(result.indirect.at(x, y), glm::vec3(0.0f))
                    << "a lone plane reflects nothing back onto itself";
            if (expected < minimumRadiance) continue;
            ++probes;
            const glm::vec3 observed = result.direct.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double expectedChannel = expected * double(light.color[c]);
                const double error =
                        std::abs(double(observed[c]) - expectedChannel) / expectedChannel;
                worst = std::max(worst, error);
                // 0.5 %: the brief's bound; the render's own error (pixel jitter, float
                // rounding) is ~0.1 %.
                EXPECT_LT(error, 0.005) << "Probe at pixel (" << x << "," << y << ") channel "
                                        << c << ": expected " << expectedChannel
                                        << " observed " << observed[c];
            }
        }
    }
    std::printf("[ probes   ] %d pixels, worst relative error %.3g%%\n", probes, 100.0 * worst);
    EXPECT_GT(probes, 300);
}

TEST(ReferenceAnalytic, PlaneUnderPointLightMatchesInverseSquareLaw) {
    const scene::Scene scene = loadPlaneScene();
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, scene::LightType::Point);
    expectPlaneMatches(scene.lights[0], 0.0);
}

TEST(ReferenceAnalytic, PlaneUnderPointLightAtAnyScale) {
    const scene::Scene scene = loadPlaneScene();
    ASSERT_EQ(scene.lights.size(), 1u);
    expectPlaneMatches(scene.lights[0], 0.0, 1e-3f);
    expectPlaneMatches(scene.lights[0], 0.0, 1e4f);
}

TEST(ReferenceAnalytic, PlaneUnderSpotLightFollowsSquaredSmoothstepFalloff) {
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = glm::vec3(0.2f, 1.0f, -0.1f);
    spot.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.2f));
    spot.color = glm::vec3(1.0f, 0.5f, 0.25f);
    spot.intensity = 2.0f;
    spot.innerConeAngle = glm::radians(15.0f);
    spot.outerConeAngle = glm::radians(40.0f);
    // Only pixels with a non-negligible value (0.05, ~1/4 of the peak): the falloff's kink at
    // the outer cone makes the field non-smooth across a pixel there, where 64 jittered paths
    // cannot average to 0.5 %.
    expectPlaneMatches(spot, 0.05);
}

TEST(ReferenceAnalytic, PlaneUnderDirectionalLightIsIntensityTimesCosine) {
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.5f));
    sun.intensity = 3.0f;
    sun.range = 0.5f;   // must be ignored (DESIGN.md)
    expectPlaneMatches(sun, 0.0);
}

TEST(ReferenceAnalytic, PointLightIgnoresRange) {
    scene::Scene scene = loadPlaneScene();
    ASSERT_EQ(scene.lights.size(), 1u);
    scene::Light light = scene.lights[0];
    light.range = 0.1f;   // far closer than the plane; DESIGN.md: never attenuates
    expectPlaneMatches(light, 0.0);
}

// Every path in the box sees Le at every vertex and has throughput rho^j after j bounces, so
// the estimate has no variance: L = Le (1 + rho + ... + rho^k) exactly, up to float rounding
// and to paths escaping through the edges (which watertight intersection prevents).
void expectClosedBox(float scale, int bounces) {
    const float rho = 0.5f;
    const glm::vec3 le(1.0f, 0.5f, 0.25f);
    const scene::Scene box = test::closedBox(glm::vec3(rho), le, scale);
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.3f, -0.2f, 0.1f) * scale,
            glm::vec3(1.0f, 0.6f, -0.8f) * scale, glm::radians(100.0f), 1.0f, box.bounds);
    constexpr int kSize = 24;
    const ReferenceResult result =
            renderReference(box, camera, kSize, kSize, referenceSettings(8, bounces));
    ASSERT_EQ(result.width(), kSize);
    const double series = (1.0 - std::pow(double(rho), bounces + 1)) / (1.0 - double(rho));
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            ASSERT_FLOAT_EQ(result.coverage[std::size_t(y) * kSize + std::size_t(x)], 1.0f)
                    << "pixel (" << x << "," << y << ") sees out of the closed box";
            for (int c = 0; c < 3; ++c) {
                const double expectedFinal = double(le[c]) * series;
                const double errFinal =
                        std::abs(double(result.final.at(x, y)[c]) - expectedFinal) / expectedFinal;
                const double errDirect =
                        std::abs(double(result.direct.at(x, y)[c]) - le[c]) / le[c];
                const double expectedIndirect = expectedFinal - double(le[c]);
                const double errIndirect =
                        std::abs(double(result.indirect.at(x, y)[c]) - expectedIndirect) /
                        expectedIndirect;
                worst = std::max({worst, errFinal, errIndirect});
                // 1e-4: float accumulation and rounding only; one escaped path in a pixel's 8
                // would already be a 5 % error, so this also proves the box is watertight at
                // every scale.
                EXPECT_LT(errFinal, 1e-4) << "final at (" << x << "," << y << ") channel " << c
                                          << ": " << result.final.at(x, y)[c] << " expected "
                                          << expectedFinal;
                EXPECT_LT(errIndirect, 1e-4) << "indirect at (" << x << "," << y << ")";
                EXPECT_LT(errDirect, 1e-6) << "direct is the wall's own emission";
            }
        }
    }
    std::printf("[ box      ] scale %g, %d bounces: worst relative error %.3g\n", double(scale),
            bounces, worst);
    // Every path has the same contribution: the halves differ by float rounding only.
    EXPECT_LT(result.noise.final, 1e-6);
}

TEST(ReferenceAnalytic, ClosedBoxConvergesToLeOverOneMinusRho) {
    // 16 bounces: the series is within rho^17 / 1 = 8e-6 of Le / (1 - rho), far inside the
    // brief's 1 % bound; the test checks the exact truncated sum, which is stricter.
    expectClosedBox(1.0f, 16);
    const double limit = 1.0 / (1.0 - 0.5);
    EXPECT_LT(std::abs((1.0 - std::pow(0.5, 17)) / (1.0 - 0.5) - limit) / limit, 0.001);
}

TEST(ReferenceAnalytic, ClosedBoxAfterKBouncesIsTheTruncatedSeries) {
    expectClosedBox(1.0f, 1);
    expectClosedBox(1.0f, 3);
}

TEST(ReferenceAnalytic, ClosedBoxIsWatertightAtAnyScale) {
    expectClosedBox(1e-3f, 4);
    expectClosedBox(1e4f, 4);
}

// Flux balance in a closed box (half-size s, albedo rho) lit by one punctual light of flux Phi
// inside it: every photon hits a wall, so the irradiance integrated over all walls is Phi after
// the light, rho Phi after one bounce, rho^2 Phi after two, and the radiance integrated over
// the walls is rho^(j+1) Phi / pi for the light scattered j times. Six 90-degree views from
// the centre see the six walls exactly, each pixel an equal square of (2s/W)^2 on its wall,
// so the sum of pixel values times that area is the integral. This checks next-event
// estimation and the light-vertex connections with their MIS weights (a light 5 % of the box
// from the ceiling makes the connections carry most of the first bounce).
void expectFluxBalance(const scene::Light& light, double flux, int bounces) {
    constexpr float kHalf = 1.0f;
    constexpr double kRho = 0.5;
    scene::Scene box = test::closedBox(glm::vec3(float(kRho)), glm::vec3(0.0f), kHalf);
    box.lights.push_back(light);
    constexpr int kSize = 64;
    const ReferenceRenderer renderer(box);
    ASSERT_TRUE(renderer.valid()) << renderer.error();
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    double direct = 0.0, indirect = 0.0, noise = 0.0;
    for (const glm::vec3& axis : axes) {
        const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f), axis,
                glm::radians(90.0f), 1.0f, box.bounds);
        const ReferenceResult result =
                renderer.render(camera, kSize, kSize, referenceSettings(64, bounces));
        for (std::size_t i = 0; i < result.final.rgb.size(); i += 3) {
            direct += result.direct.rgb[i];
            indirect += result.indirect.rgb[i];
        }
        noise = std::max(noise, result.noise.indirect);
        for (float c : result.coverage) ASSERT_FLOAT_EQ(c, 1.0f);
    }
    const double pixelArea = std::pow(2.0 * kHalf / kSize, 2.0);
    direct *= pixelArea;
    indirect *= pixelArea;
    const double expectedDirect = kRho * flux / glm::pi<double>();
    double expectedIndirect = 0.0;
    for (int j = 2; j <= bounces + 1; ++j) {
        expectedIndirect += std::pow(kRho, j) * flux / glm::pi<double>();
    }
    std::printf("[ flux     ] %d bounces: direct %.6f (expected %.6f), indirect %.6f (expected "
                "%.6f); per-pixel indirect noise %.3g%%\n",
            bounces, direct, expectedDirect, indirect, expectedIndirect, 100.0 * noise);
    // 0.2 %: the sums run over 6 x 64^2 pixels, so the per-pixel noise (a few %) averages to
    // ~0.05 %; pixel-footprint integration of the hot spot under the light is exact in
    // expectation.
    EXPECT_NEAR(direct, expectedDirect, 0.002 * expectedDirect);
    EXPECT_NEAR(indirect, expectedIndirect, 0.002 * expectedIndirect);
}

TEST(ReferenceAnalytic, PointLightFluxBalancesInClosedBox) {
    scene::Light light;
    light.position = glm::vec3(0.1f, 0.95f, -0.2f);   // 5 cm under the ceiling of a 2 m box
    light.intensity = 1.5f;
    const double flux = 4.0 * glm::pi<double>() * light.intensity;
    expectFluxBalance(light, flux, 1);
    expectFluxBalance(light, flux, 3);
}

TEST(ReferenceAnalytic, SpotLightFluxBalancesInClosedBox) {
    scene::Light light;
    light.type = scene::LightType::Spot;
    light.position = glm::vec3(-0.3f, 0.2f, 0.1f);
    light.direction = glm::normalize(glm::vec3(1.0f, -0.5f, 0.3f));
    light.intensity = 2.0f;
    light.innerConeAngle = glm::radians(20.0f);
    light.outerConeAngle = glm::radians(50.0f);
    // Phi = I x integral of s^2 over the sphere = 2 pi I [(1 - cos ti) + (cos ti - cos to) / 3].
    const double ci = std::cos(double(light.innerConeAngle));
    const double co = std::cos(double(light.outerConeAngle));
    const double flux = 2.0 * glm::pi<double>() * light.intensity * ((1.0 - ci) + (ci - co) / 3.0);
    expectFluxBalance(light, flux, 1);
}

// Irradiance at x (unit normal n) from a uniformly emitting polygon of radiance le, by
// Lambert's formula E = le/2 |sum_i theta_i n . (r_i x r_(i+1)) / |r_i x r_(i+1)||, r_i the
// unit vectors from x to the corners, theta_i the angle between r_i and r_(i+1). Exact for a
// polygon wholly above the tangent plane.
double polygonIrradiance(const glm::dvec3& x, const glm::dvec3& n,
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

TEST(ReferenceAnalytic, LambertPolygonFormulaMatchesNumericIntegration) {
    // Checks the test's own expectation: E = le sum dA cos(theta_r) cos(theta_e) / r^2 over a
    // 400 x 400 grid of the emitter, whose discretisation error is ~1e-5.
    const std::vector<glm::dvec3> square = {{-0.5, 0.5, -0.5}, {0.5, 0.5, -0.5},
            {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}};
    for (const glm::dvec3 x :
            {glm::dvec3(0.0), glm::dvec3(0.3, 0.0, -0.2), glm::dvec3(0.9, 0.0, 0.4)}) {
        constexpr int kN = 400;
        double numeric = 0.0;
        const double da = 1.0 / (kN * kN);
        for (int j = 0; j < kN; ++j) {
            for (int i = 0; i < kN; ++i) {
                const glm::dvec3 q(-0.5 + (i + 0.5) / kN, 0.5, -0.5 + (j + 0.5) / kN);
                const glm::dvec3 d = q - x;
                const double r2 = glm::dot(d, d);
                const double cosR = d.y / std::sqrt(r2);
                numeric += da * cosR * cosR / r2;   // cos at emitter = cos at receiver here
            }
        }
        EXPECT_NEAR(polygonIrradiance(x, {0, 1, 0}, square, 1.0), numeric, 1e-4 * numeric);
    }
}

// A square emitter (side 1 x scale, radiance Le, black) 0.5 x scale above a receiver plane
// (albedo rho, no lights). Irradiance from an emitter is scale-invariant, so the expected
// image is the same at every scale; at 1e-3 and 1e4 this checks that ray offsets follow it.
void expectSquareEmitterMatches(float scale, int spp) {
    scene::Scene scene;
    const glm::vec3 le(2.0f, 1.0f, 0.5f);
    const glm::vec3 rho(0.8f, 0.6f, 0.4f);
    const int emitter = test::addMaterial(scene, glm::vec3(0.0f), le);
    const int receiver = test::addMaterial(scene, rho);
    const double height = 0.5 * scale, half = 0.5 * scale, receiverHalf = 4.0 * scale;
    const float h = float(height), a = float(half), r = float(receiverHalf);
    test::addQuad(scene, {glm::vec3(-a, h, -a), glm::vec3(a, h, -a), glm::vec3(a, h, a),
                                 glm::vec3(-a, h, a)},
            emitter);   // faces -y
    test::addQuad(scene, {glm::vec3(-r, 0, r), glm::vec3(r, 0, r), glm::vec3(r, 0, -r),
                                 glm::vec3(-r, 0, -r)},
            receiver);   // faces +y
    const std::vector<glm::dvec3> polygon = {{-half, height, -half}, {half, height, -half},
            {half, height, half}, {-half, height, half}};

    constexpr int kSize = 48;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, 0.45f, 1.2f) * scale,
            glm::vec3(0.0f, 0.0f, -0.1f) * scale, glm::radians(50.0f), 1.0f, scene.bounds);
    const ReferenceResult result =
            renderReference(scene, camera, kSize, kSize, referenceSettings(spp, 1));
    ASSERT_EQ(result.width(), kSize);
    printNoise("square emitter", result);
    ASSERT_TRUE(std::isfinite(result.noise.indirect));

    // Compare 4 x 4 pixel blocks, whose mean has a quarter of the per-pixel noise.
    constexpr int kBlock = 4;
    int blocks = 0;
    double worst = 0.0;
    for (int by = 0; by < kSize; by += kBlock) {
        for (int bx = 0; bx < kSize; bx += kBlock) {
            glm::dvec3 expected(0.0), observed(0.0);
            bool inside = true;
            for (int y = by; y < by + kBlock && inside; ++y) {
                for (int x = bx; x < bx + kBlock && inside; ++x) {
                    double e = 0.0;
                    // 8 x 8 sub-positions: E varies smoothly over a pixel (< 2 % across it),
                    // so the midpoint rule's error is ~1e-4.
                    inside = footprintMean(camera, kSize, kSize, x, y, receiverHalf, 8,
                            [&](const glm::dvec3& p) {
                                return polygonIrradiance(p, {0, 1, 0}, polygon, 1.0);
                            },
                            e);
                    if (!inside) break;
                    expected += glm::dvec3(rho) * glm::dvec3(le) * (e / glm::pi<double>());
                    observed += glm::dvec3(result.indirect.at(x, y));
                    EXPECT_EQ(result.direct.at(x, y), glm::vec3(0.0f)) << "no lights";
                }
            }
            // Only blocks where the emitter fills a good part of the hemisphere: elsewhere the
            // relative noise of a block exceeds what the 1 % bound can resolve.
            if (!inside || expected.r / (kBlock * kBlock) < 0.25 * double(rho.r * le.r)) continue;
            ++blocks;
            // Noise of a block mean: the image's relative noise / sqrt(16) pixels, times 4
            // for a 4-sigma bound; plus the brief's 1 % for the model itself.
            const double tolerance = 0.01 + 4.0 * result.noise.indirect / kBlock;
            for (int c = 0; c < 3; ++c) {
                const double error = std::abs(observed[c] - expected[c]) / expected[c];
                worst = std::max(worst, error);
                EXPECT_LT(error, tolerance) << "block at (" << bx << "," << by << ") channel "
                                            << c << ": expected " << expected[c] / 16
                                            << " observed " << observed[c] / 16;
            }
        }
    }
    std::printf("[ probes   ] scale %g: %d blocks, worst relative error %.3g%%\n",
            double(scale), blocks, 100.0 * worst);
    EXPECT_GT(blocks, 10);
}

TEST(ReferenceAnalytic, OneBounceFromSquareEmitterMatchesLambertFormula) {
    expectSquareEmitterMatches(1.0f, 1024);
}

TEST(ReferenceAnalytic, OneBounceIsScaleInvariant) {
    expectSquareEmitterMatches(1e-3f, 256);
    expectSquareEmitterMatches(1e4f, 256);
}

TEST(ReferenceAnalytic, AlphaMaskCutsOutCameraAndShadowRays) {
    // A quad at z = 0 whose base-colour texture is 2 x 1 texels: left texel alpha 0 (cut out),
    // right texel sRGB 188 (linear 0.5029) with alpha 255. A backdrop (albedo 0.25) at z = -1.
    // A directional light shines along -z. Through the cut-out half the camera sees the
    // backdrop lit (the shadow ray passes the cut-out); the right half shows the texture.
    scene::Scene scene;
    scene::Texture texture;
    texture.width = 2;
    texture.height = 1;
    texture.rgba8 = {188, 188, 188, 0, 188, 188, 188, 255};
    texture.wrapS = texture.wrapT = 33071;   // CLAMP_TO_EDGE
    scene.textures.push_back(texture);
    const int masked = test::addMaterial(scene, glm::vec3(1.0f));
    scene.materials[std::size_t(masked)].baseColorTexture = 0;
    scene.materials[std::size_t(masked)].alphaMode = scene::AlphaMode::Mask;
    const int backdrop = test::addMaterial(scene, glm::vec3(0.25f));
    test::addQuad(scene, {glm::vec3(-4, -4, -1), glm::vec3(4, -4, -1), glm::vec3(4, 4, -1),
                                 glm::vec3(-4, 4, -1)},
            backdrop);
    test::addQuad(scene, {glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(1, 1, 0),
                                 glm::vec3(-1, 1, 0)},
            masked);
    auto& quad = scene.primitives.back();
    quad.texcoords0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(0, 0, -1);
    sun.intensity = 2.0f;
    scene.lights.push_back(sun);

    constexpr int kSize = 32;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0, 0, 3), glm::vec3(0),
            glm::radians(30.0f), 1.0f, scene.bounds);
    const ReferenceResult result =
            renderReference(scene, camera, kSize, kSize, referenceSettings(16, 1));
    const double texel = double(core::srgbToLinear(188.0f / 255.0f));
    int left = 0, right = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // Pixels whose whole footprint is on one half of the quad, away from the middle
            // where bilinear filtering blends the two texels.
            bool allLeft = true, allRight = true;
            for (double dy : {0.0, 1.0}) {
                for (double dx : {0.0, 1.0}) {
                    const PixelRay ray = pixelRay(camera, kSize, kSize, x + dx, y + dy);
                    const glm::dvec3 p =
                            ray.origin - (ray.origin.z / ray.direction.z) * ray.direction;
                    const bool onQuad = std::abs(p.x) < 0.95 && std::abs(p.y) < 0.95;
                    allLeft = allLeft && onQuad && p.x < -0.6;
                    allRight = allRight && onQuad && p.x > 0.6;
                }
            }
            const glm::vec3 value = result.direct.at(x, y);
            // 1e-5 relative: no noise (every path sees the same surface and the same light);
            // float rounding only.
            if (allRight) {
                ++right;
                EXPECT_NEAR(value.g, texel / glm::pi<double>() * 2.0, 1e-5);
            }
            if (allLeft) {
                ++left;
                EXPECT_NEAR(value.g, 0.25 / glm::pi<double>() * 2.0, 1e-5)
                        << "the backdrop behind the cut-out is visible and lit";
            }
        }
    }
    EXPECT_GT(left, 20);
    EXPECT_GT(right, 20);
}

TEST(ReferenceAnalytic, ImageIsIdenticalForAnyThreadCount) {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::loadGltf(std::string(VOXATLAS_DATA_DIR) +
                                        "/assets/cornell_box/cornell_box.gltf",
            scene, error, warnings))
            << error;
    ASSERT_FALSE(scene.cameras.empty());
    constexpr int kSize = 40;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    const ReferenceRenderer renderer(scene);
    ASSERT_TRUE(renderer.valid()) << renderer.error();
    const ReferenceResult one =
            renderer.render(camera, kSize, kSize, referenceSettings(8, 2, 7, 1));
    const ReferenceResult two =
            renderer.render(camera, kSize, kSize, referenceSettings(8, 2, 7, 2));
    const ReferenceResult other =
            renderer.render(camera, kSize, kSize, referenceSettings(8, 2, 8, 2));
    ASSERT_EQ(one.final.rgb.size(), two.final.rgb.size());
    for (const auto member : {&ReferenceResult::direct, &ReferenceResult::indirect,
                 &ReferenceResult::final}) {
        EXPECT_EQ(std::memcmp((one.*member).rgb.data(), (two.*member).rgb.data(),
                          (one.*member).rgb.size() * sizeof(float)),
                0);
    }
    EXPECT_EQ(one.coverage, two.coverage);
    EXPECT_EQ(one.rays.total(), two.rays.total());
    EXPECT_EQ(one.noise.final, two.noise.final);
    EXPECT_NE(one.final.rgb, other.final.rgb) << "another seed gives other samples";
    printNoise("cornell box", one);
}

} // namespace
} // namespace gi::reference
