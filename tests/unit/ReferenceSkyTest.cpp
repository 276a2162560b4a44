// The sky in the ground-truth renderer: a constant radiance L from every direction no geometry
// blocks. An open plane of albedo rho shows rho L exactly (E = pi L), with any number of
// bounces; the floor centre of a box open at the top receives E = L x the opening's Lambert
// polygon factor as direct light, and its final radiance after bounces is printed.
#include "ReferenceAnalyticSupport.h"
#include "ReferenceTestScenes.h"
#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace gi::reference {
namespace {

using test::referenceSettings;
using test::twoSeedNoise;

scene::Light sky(const glm::vec3& color, float intensity) {
    scene::Light light;
    light.type = scene::LightType::Sky;
    light.color = color;
    light.intensity = intensity;
    return light;
}

TEST(ReferenceSky, OpenPlaneShowsRhoTimesL) {
    scene::Scene scene;
    const glm::vec3 rho(0.8f, 0.5f, 0.2f);
    test::addQuad(scene, {glm::vec3(-100, 0, 100), glm::vec3(100, 0, 100),
                                 glm::vec3(100, 0, -100), glm::vec3(-100, 0, -100)},
            test::addMaterial(scene, rho));
    scene.lights.push_back(sky(glm::vec3(0.5f, 1.0f, 2.0f), 1.5f));
    const glm::vec3 radiance = rho * glm::vec3(0.75f, 1.5f, 3.0f);
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, 1.0f, 0.0f),
            glm::vec3(0.0f), glm::radians(60.0f), 1.0f, scene.bounds);
    constexpr int kSize = 16;
    const ReferenceRenderer renderer(scene);
    for (int bounces : {0, 1, 3}) {
        const ReferenceResult result =
                renderer.render(camera, kSize, kSize, referenceSettings(8, bounces));
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                // Every sampled direction escapes: no noise, float rounding only.
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(result.direct.at(x, y)[c], radiance[c], 1e-6f * radiance[c])
                            << bounces << " bounces, pixel (" << x << "," << y << ")";
                }
                EXPECT_EQ(result.indirect.at(x, y), glm::vec3(0.0f));
            }
        }
    }
}

// The cube [-1, 1]^3 without its ceiling, walls of albedo 0.5 facing in, under a white sky.
TEST(ReferenceSky, HalfOpenBoxFloorCentreSeesTheOpening) {
    constexpr float kRho = 0.5f;
    scene::Scene box;
    const int material = test::addMaterial(box, glm::vec3(kRho));
    const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
            {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    test::addQuad(box, {c[0], c[1], c[2], c[3]}, material);
    test::addQuad(box, {c[5], c[4], c[7], c[6]}, material);
    test::addQuad(box, {c[4], c[0], c[3], c[7]}, material);
    test::addQuad(box, {c[1], c[5], c[6], c[2]}, material);
    test::addQuad(box, {c[4], c[5], c[1], c[0]}, material);   // floor, faces +y
    box.lights.push_back(sky(glm::vec3(1.0f), 1.0f));
    const double factor = test::polygonIrradiance({0, -1, 0}, {0, 1, 0},
            {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}, 1.0);   // E / L = 0.7523
    EXPECT_NEAR(factor, 4.0 * (0.5 / std::sqrt(1.25)) * std::atan(0.5 / std::sqrt(1.25)), 1e-9);

    constexpr int kSize = 8;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, -0.75f, 0.0f),
            glm::vec3(0.0f, -1.0f, 0.0f), glm::radians(2.0f), 1.0f, box.bounds);
    const ReferenceRenderer renderer(box);
    for (int bounces : {0, 1, 4}) {
        const ReferenceResult a =
                renderer.render(camera, kSize, kSize, referenceSettings(256, bounces, 1));
        const ReferenceResult b =
                renderer.render(camera, kSize, kSize, referenceSettings(256, bounces, 2));
        double direct = 0.0, final = 0.0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                direct += double(a.direct.at(x, y).g + b.direct.at(x, y).g);
                final += double(a.final.at(x, y).g + b.final.at(x, y).g);
            }
        }
        direct /= 2.0 * kSize * kSize;
        final /= 2.0 * kSize * kSize;
        const double noise = twoSeedNoise(a.direct, b.direct, [](int, int) { return true; }) /
                             std::sqrt(2.0 * kSize * kSize);
        const double expected = kRho * factor / glm::pi<double>();
        std::printf("[ sky      ] half-open box, floor centre, %d bounces: direct %.5f "
                    "(expected %.5f, mean's noise %.3g%%), final %.5f (= %.4f L)\n",
                bounces, direct, expected, 100.0 * noise, final, final);
        EXPECT_NEAR(direct, expected, expected * (2e-3 + 4.0 * noise));
        EXPECT_GE(final, direct);
    }
}

} // namespace
} // namespace gi::reference
