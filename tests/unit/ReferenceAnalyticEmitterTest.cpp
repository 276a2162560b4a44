// Physics tests of the ground-truth renderer with an area emitter: a square emitter over a
// receiver, whose direct light L = rho/pi x E with E from Lambert's polygon formula (Arvo,
// "Applications of Irradiance Tensors...", SIGGRAPH 1995); alpha-mask cut-outs in camera and
// shadow rays with sRGB texture decoding; and determinism across thread counts.
#include "ReferenceAnalyticSupport.h"
#include "ReferenceTestScenes.h"
#include "core/Colour.h"
#include "reference/ReferenceRenderer.h"
#include "scene/EmissionLights.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace gi::reference {
namespace {

using test::PixelRay;
using test::footprintMean;
using test::pixelRay;
using test::printNoise;
using test::polygonIrradiance;
using test::referenceSettings;

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
// (albedo rho, no other lights). Irradiance from an emitter is scale-invariant, so the
// expected image is the same at every scale; at 1e-3 and 1e4 this checks that ray offsets
// follow it. The receiver's light is direct light: the emission a bounce from the camera hit
// finds belongs to the direct term, like the emitter's next-event estimate when the square is
// an area light (emitterIsLight, as loading a file makes it); otherwise bounces find it alone.
void expectSquareEmitterMatches(float scale, int spp, bool emitterIsLight) {
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
    if (emitterIsLight) ASSERT_EQ(scene::addEmissionLights(scene).lights, 1u);
    const std::vector<glm::dvec3> polygon = {{-half, height, -half}, {half, height, -half},
            {half, height, half}, {-half, height, half}};

    constexpr int kSize = 48;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, 0.45f, 1.2f) * scale,
            glm::vec3(0.0f, 0.0f, -0.1f) * scale, glm::radians(50.0f), 1.0f, scene.bounds);
    // Two halves of the samples with their own seeds: their difference measures the noise
    // over exactly the pixels compared (the camera also sees the bright emitter's underside,
    // which would dilute the image-wide estimate).
    const ReferenceRenderer renderer(scene);
    const ReferenceResult first =
            renderer.render(camera, kSize, kSize, referenceSettings(spp / 2, 1, 1));
    const ReferenceResult second =
            renderer.render(camera, kSize, kSize, referenceSettings(spp / 2, 1, 2));
    ASSERT_EQ(first.width(), kSize);
    printNoise(emitterIsLight ? "square area light" : "square emitter found by bounces", first);
    auto onReceiver = [&](int x, int y) {
        double e = 0.0;
        return footprintMean(camera, kSize, kSize, x, y, receiverHalf, 1,
                [](const glm::dvec3&) { return 0.0; }, e);
    };
    const double noise = test::twoSeedNoise(first.direct, second.direct, onReceiver) /
                         std::sqrt(2.0);
    ASSERT_TRUE(std::isfinite(noise));
    std::printf("[ noise    ] receiver direct light, %d spp: %.3g%%\n", spp, 100.0 * noise);

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
                    observed += 0.5 * (glm::dvec3(first.direct.at(x, y)) +
                                       glm::dvec3(second.direct.at(x, y)));
                    EXPECT_EQ(first.indirect.at(x, y), glm::vec3(0.0f))
                            << "a bounce from the receiver finds only the black emitter";
                }
            }
            // Only blocks where the emitter fills a good part of the hemisphere: elsewhere the
            // relative noise of a block exceeds what the 1 % bound can resolve.
            if (!inside || expected.r / (kBlock * kBlock) < 0.25 * double(rho.r * le.r)) continue;
            ++blocks;
            // Noise of a block mean: the pixels' relative noise / sqrt(16) pixels, times 4
            // for a 4-sigma bound; plus the brief's 1 % for the model itself.
            const double tolerance = 0.01 + 4.0 * noise / kBlock;
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

TEST(ReferenceAnalytic, SquareEmitterFoundByBouncesMatchesLambertFormula) {
    expectSquareEmitterMatches(1.0f, 1024, false);
}

TEST(ReferenceAnalytic, SquareAreaLightMatchesLambertFormula) {
    expectSquareEmitterMatches(1.0f, 64, true);
}

TEST(ReferenceAnalytic, EmitterLightIsScaleInvariant) {
    expectSquareEmitterMatches(1e-3f, 256, false);
    expectSquareEmitterMatches(1e4f, 256, false);
    expectSquareEmitterMatches(1e-3f, 64, true);
    expectSquareEmitterMatches(1e4f, 64, true);
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
