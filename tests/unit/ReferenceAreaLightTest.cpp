// Area lights in the ground-truth renderer: next-event estimation of an emitting square gives
// the point-to-square irradiance at the floor under it (with and without a bounce to weigh it
// against); emission leaves the front side only unless the material is double-sided, for
// light samples and bounce hits alike; a command-line rectangle (no geometry) lights like
// the same square as geometry; walls that are all area lights keep the closed box's exact
// series (the MIS weights sum to one); and the emissive Cornell box's direct light is at
// least 10x less noisy than the estimate of bounce hits alone.
#include "ReferenceAnalyticSupport.h"
#include "ReferenceTestScenes.h"
#include "app/LightSpec.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "scene/EmissionLights.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace gi::reference {
namespace {

using test::referenceSettings;
using test::twoSeedNoise;

const glm::vec3 kLe(2.0f, 1.0f, 0.5f);
const glm::vec3 kRho(0.8f, 0.6f, 0.4f);

enum class Emitter { FacingFloor, FacingAway, FacingAwayDoubleSided, None };

// A 1 m square of radiance kLe (black) 0.5 m above the centre of an 8 m floor of albedo kRho,
// made an area light as loading a file does.
scene::Scene squareOverFloor(Emitter emitter) {
    scene::Scene scene;
    const int receiver = test::addMaterial(scene, kRho);
    test::addQuad(scene, {glm::vec3(-4, 0, 4), glm::vec3(4, 0, 4), glm::vec3(4, 0, -4),
                                 glm::vec3(-4, 0, -4)},
            receiver);
    if (emitter == Emitter::None) return scene;
    const int material = test::addMaterial(scene, glm::vec3(0.0f), kLe);
    scene.materials[std::size_t(material)].doubleSided =
            emitter == Emitter::FacingAwayDoubleSided;
    std::array<glm::vec3, 4> corners = {glm::vec3(-0.5f, 0.5f, -0.5f),
            glm::vec3(0.5f, 0.5f, -0.5f), glm::vec3(0.5f, 0.5f, 0.5f),
            glm::vec3(-0.5f, 0.5f, 0.5f)};   // faces -y
    if (emitter != Emitter::FacingFloor) std::swap(corners[1], corners[3]);
    test::addQuad(scene, corners, material);
    EXPECT_EQ(scene::addEmissionLights(scene).lights, 1u);
    return scene;
}

// The floor's radiance at its centre, seen from 0.25 m above through a 2-degree view (its
// footprint, 9 mm wide, changes E by < 1e-4), as the mean of 8 x 8 pixels and that mean's
// relative noise (from two seeds).
struct FloorCentre {
    glm::dvec3 direct{0.0}, indirect{0.0};
    double noise = 0.0;
};

FloorCentre renderFloorCentre(const scene::Scene& scene, int spp, int bounces) {
    constexpr int kSize = 8;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, 0.25f, 0.0f),
            glm::vec3(0.0f), glm::radians(2.0f), 1.0f, scene.bounds);
    const ReferenceRenderer renderer(scene);
    const ReferenceResult a =
            renderer.render(camera, kSize, kSize, referenceSettings(spp, bounces, 1));
    const ReferenceResult b =
            renderer.render(camera, kSize, kSize, referenceSettings(spp, bounces, 2));
    FloorCentre centre;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            centre.direct += glm::dvec3(a.direct.at(x, y)) + glm::dvec3(b.direct.at(x, y));
            centre.indirect += glm::dvec3(a.indirect.at(x, y)) + glm::dvec3(b.indirect.at(x, y));
        }
    }
    centre.direct /= 2.0 * kSize * kSize;
    centre.indirect /= 2.0 * kSize * kSize;
    // The mean of 2 x 64 pixels: 1/sqrt(128) of one render's per-pixel noise.
    centre.noise = twoSeedNoise(a.direct, b.direct, [](int, int) { return true; }) /
                   std::sqrt(2.0 * kSize * kSize);
    return centre;
}

// E at the centre under a square of side 1 at height 0.5: four 0.5 x 0.5 rectangles seen from
// their corner, 4 L X/sqrt(1+X^2) atan(X/sqrt(1+X^2)) with X = 1 (= 1.7408 L).
double squareIrradianceFactor() {
    const double s = 1.0 / std::sqrt(2.0);
    return 4.0 * s * std::atan(s);
}

void expectDirectNear(const FloorCentre& centre, double factor, const char* what) {
    std::printf("[ centre   ] %s: direct %.5f %.5f %.5f, expected %.5f %.5f %.5f; mean's "
                "noise %.3g%%\n",
            what, centre.direct.r, centre.direct.g, centre.direct.b,
            kRho.r * kLe.r * factor / glm::pi<double>(),
            kRho.g * kLe.g * factor / glm::pi<double>(),
            kRho.b * kLe.b * factor / glm::pi<double>(), 100.0 * centre.noise);
    for (int c = 0; c < 3; ++c) {
        const double expected = double(kRho[c] * kLe[c]) * factor / glm::pi<double>();
        // 4 sigma of the mean, and 2e-3 for the footprint and float rounding.
        EXPECT_NEAR(centre.direct[c], expected, expected * (2e-3 + 4.0 * centre.noise))
                << what << " channel " << c;
    }
}

TEST(ReferenceAreaLight, SquareGivesPointToSquareIrradiance) {
    EXPECT_NEAR(squareIrradianceFactor(), 1.7408, 1e-4);
    const scene::Scene scene = squareOverFloor(Emitter::FacingFloor);
    // bounces = 0: light samples alone (weight 1); 1: weighed against the bounce ray.
    const FloorCentre alone = renderFloorCentre(scene, 64, 0);
    expectDirectNear(alone, squareIrradianceFactor(), "light samples alone");
    EXPECT_LT(alone.noise, 0.01);
    const FloorCentre weighed = renderFloorCentre(scene, 64, 1);
    expectDirectNear(weighed, squareIrradianceFactor(), "light samples and bounces (MIS)");
    EXPECT_EQ(weighed.indirect, glm::dvec3(0.0)) << "the emitter is black";
}

TEST(ReferenceAreaLight, EmissionLeavesTheFrontSideUnlessDoubleSided) {
    for (int bounces : {0, 1}) {
        const FloorCentre away =
                renderFloorCentre(squareOverFloor(Emitter::FacingAway), 16, bounces);
        EXPECT_EQ(away.direct, glm::dvec3(0.0)) << "the back of a single-sided emitter is dark";
        const FloorCentre both =
                renderFloorCentre(squareOverFloor(Emitter::FacingAwayDoubleSided), 64, bounces);
        expectDirectNear(both, squareIrradianceFactor(), "double-sided, facing away");
    }
}

TEST(ReferenceAreaLight, CommandLineRectLightsLikeTheSameSquare) {
    scene::Scene scene = squareOverFloor(Emitter::None);
    scene::Light rect;
    std::string error;
    ASSERT_TRUE(app::parseLightSpec("rect:0,0.5,0:1,0,0:0,0,1:2,1,0.5:1", rect, error)) << error;
    scene.lights.push_back(rect);
    for (int bounces : {0, 2}) {
        const FloorCentre centre = renderFloorCentre(scene, 64, bounces);
        expectDirectNear(centre, squareIrradianceFactor(), "command-line rect");
    }
    scene.lights.back().emitters[0].p1 = scene.lights.back().emitters[0].p0;   // degenerate
    const FloorCentre half = renderFloorCentre(scene, 64, 0);
    expectDirectNear(half, 0.5 * squareIrradianceFactor(), "one triangle of the rect left");
}

// A closed box whose walls all emit Le and are area lights: every vertex's light now comes
// from light samples and ray hits weighted against each other, so the image is noisy, but its
// expectation is still that of the walls found by rays alone (ReferenceAnalyticBoxTest):
// Le (1 + rho + ... + rho^(k+1)) after k bounces, Le (1 + rho) of it direct.
TEST(ReferenceAreaLight, WallsAsAreaLightsKeepTheClosedBoxSeries) {
    const float rho = 0.5f;
    const glm::vec3 le(1.0f, 0.5f, 0.25f);
    scene::Scene box = test::closedBox(glm::vec3(rho), le, 1.0f);
    ASSERT_GT(scene::addEmissionLights(box).lights, 0u);
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.3f, -0.2f, 0.1f),
            glm::vec3(1.0f, 0.6f, -0.8f), glm::radians(100.0f), 1.0f, box.bounds);
    constexpr int kSize = 24, kBounces = 3;
    const ReferenceRenderer renderer(box);
    const ReferenceResult a =
            renderer.render(camera, kSize, kSize, referenceSettings(32, kBounces, 1));
    const ReferenceResult b =
            renderer.render(camera, kSize, kSize, referenceSettings(32, kBounces, 2));
    const double series = (1.0 - std::pow(double(rho), kBounces + 2)) / (1.0 - double(rho));
    glm::dvec3 direct(0.0), final(0.0);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            direct += glm::dvec3(a.direct.at(x, y)) + glm::dvec3(b.direct.at(x, y));
            final += glm::dvec3(a.final.at(x, y)) + glm::dvec3(b.final.at(x, y));
        }
    }
    const double pixels = 2.0 * kSize * kSize;
    const double noise = twoSeedNoise(a.final, b.final, [](int, int) { return true; }) /
                         std::sqrt(pixels);
    std::printf("[ box      ] walls as area lights: final %.5f (expected %.5f), direct %.5f "
                "(expected %.5f); mean's noise %.3g%%\n",
            final.r / pixels, le.r * series, direct.r / pixels, le.r * (1.0 + rho),
            100.0 * noise);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(final[c] / pixels, le[c] * series, le[c] * series * (1e-4 + 4.0 * noise));
        EXPECT_NEAR(direct[c] / pixels, le[c] * (1.0 + rho),
                le[c] * (1.0 + rho) * (1e-4 + 4.0 * noise));
    }
}

// The emissive Cornell box (a panel 1 mm under the ceiling, no other light): the direct image
// by light samples against the same scene whose panel is not a light (bounce hits alone), at
// equal samples, over the pixels that show lit geometry but not the panel itself.
TEST(ReferenceAreaLight, EmissiveCornellBoxDirectLightIsTenTimesLessNoisy) {
    scene::Scene hitsOnly;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::loadGltf(std::string(VOXATLAS_DATA_DIR) +
                                        "/assets/cornell_box/cornell_box_emissive.gltf",
            hitsOnly, error, warnings))
            << error;
    ASSERT_TRUE(hitsOnly.lights.empty());
    scene::Scene sampled = hitsOnly;
    ASSERT_EQ(scene::addEmissionLights(sampled).lights, 1u);
    constexpr int kSize = 48, kSpp = 64;
    const scene::CameraView camera =
            scene::cameraFromScene(hitsOnly.cameras.at(0), 1.0f, hitsOnly.bounds);
    const ReferenceRenderer hitRenderer(hitsOnly), sampleRenderer(sampled);
    auto render = [&](const ReferenceRenderer& renderer, int seed) {
        return renderer.render(camera, kSize, kSize, referenceSettings(kSpp, 1, seed));
    };
    const ReferenceResult hitA = render(hitRenderer, 1), hitB = render(hitRenderer, 2);
    const ReferenceResult nee = render(sampleRenderer, 1), neeB = render(sampleRenderer, 2);
    // The panel (radiance ~ 20) shows in a few pixels; lit walls stay under 1.
    auto litWall = [&](int x, int y) {
        const std::size_t pixel = std::size_t(y) * kSize + std::size_t(x);
        return nee.coverage[pixel] > kGeometryCoverage && nee.direct.at(x, y).g < 1.0f &&
               neeB.direct.at(x, y).g < 1.0f;
    };
    const double hitNoise = twoSeedNoise(hitA.direct, hitB.direct, litWall);
    const double neeNoise = twoSeedNoise(nee.direct, neeB.direct, litWall);
    double hitMean = 0.0, neeMean = 0.0;
    int pixels = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!litWall(x, y)) continue;
            ++pixels;
            hitMean += double(hitA.direct.at(x, y).g + hitB.direct.at(x, y).g);
            neeMean += double(nee.direct.at(x, y).g + neeB.direct.at(x, y).g);
        }
    }
    std::printf("[ cornell  ] emissive box, %dx%d, %d spp, direct light over %d wall pixels: "
                "relative noise %.2f%% by bounce hits alone, %.2f%% with light samples "
                "(%.1fx less); mean %.5f vs %.5f\n",
            kSize, kSize, kSpp, pixels, 100.0 * hitNoise, 100.0 * neeNoise, hitNoise / neeNoise,
            hitMean / (2.0 * pixels), neeMean / (2.0 * pixels));
    EXPECT_GT(pixels, kSize * kSize / 2);
    EXPECT_LT(neeNoise, 0.08);
    EXPECT_GT(hitNoise / neeNoise, 10.0);
    // Both estimate the same light: their means over ~1500 pixels agree within the hits'
    // noise (~60 % per pixel, ~1.5 % for the mean of both seeds; 4 sigma).
    EXPECT_NEAR(hitMean / neeMean, 1.0, 4.0 * hitNoise / std::sqrt(2.0 * pixels) + 0.005);
}

} // namespace
} // namespace gi::reference
