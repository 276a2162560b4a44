// The path tracer's glossy model (ReferenceSettings::glossy, reference/GltfBrdf.h) against a
// case with a known answer: a shiny metal floor under a square emitter shows the emitter's
// radiance times the BRDF integrated over the square (about the Fresnel reflectance where
// the mirror ray meets it, nothing far from it), which the Lambertian floor does not.
#include "ReferenceAnalyticSupport.h"
#include "ReferenceTestScenes.h"
#include "reference/GltfBrdf.h"
#include "reference/ReferenceRenderer.h"
#include "scene/EmissionLights.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace gi::reference {
namespace {

using test::pixelRay;
using test::referenceSettings;

constexpr float kEmitterHeight = 0.5f;
constexpr float kEmitterHalf = 0.5f;

struct MirrorScene {
    scene::Scene scene;
    glm::vec3 le{2.0f, 1.0f, 0.5f};
    glm::vec3 baseColor{0.9f, 0.8f, 0.7f};
    float roughness = 0.0f;
};

MirrorScene mirrorScene(float roughness) {
    MirrorScene s;
    s.roughness = roughness;
    const int emitter = test::addMaterial(s.scene, glm::vec3(0.0f), s.le);
    const int floor = test::addMaterial(s.scene, s.baseColor);
    s.scene.materials[std::size_t(floor)].metallicFactor = 1.0f;
    s.scene.materials[std::size_t(floor)].roughnessFactor = roughness;
    const float h = kEmitterHeight, a = kEmitterHalf, r = 4.0f;
    test::addQuad(s.scene, {glm::vec3(-a, h, -a), glm::vec3(a, h, -a), glm::vec3(a, h, a),
                                   glm::vec3(-a, h, a)},
            emitter);   // faces -y
    test::addQuad(s.scene, {glm::vec3(-r, 0, r), glm::vec3(r, 0, r), glm::vec3(r, 0, -r),
                                   glm::vec3(-r, 0, -r)},
            floor);   // faces +y
    scene::addEmissionLights(s.scene);
    return s;
}

// Radiance the floor point seen through pixel (x, y)'s centre reflects towards the camera:
// Le x the integral of f cos over the emitter (midpoint rule on a kGrid^2 grid); false when
// the pixel does not see the floor.
constexpr int kGrid = 240;

bool expectedReflection(const MirrorScene& s, const scene::CameraView& camera, int size,
        int x, int y, glm::dvec3& radiance) {
    const test::PixelRay ray = pixelRay(camera, size, size, x + 0.5, y + 0.5);
    if (ray.direction.y >= 0.0) return false;
    const glm::dvec3 hit = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
    const GltfBrdf brdf = makeGltfBrdf(s.baseColor, 1.0f, s.roughness);
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 v = glm::vec3(-ray.direction);
    const double cell = 2.0 * kEmitterHalf / kGrid;
    glm::dvec3 sum(0.0);
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const glm::dvec3 q(-kEmitterHalf + (i + 0.5) * cell, kEmitterHeight,
                    -kEmitterHalf + (j + 0.5) * cell);
            const glm::dvec3 d = q - hit;
            const double r2 = glm::dot(d, d);
            const glm::dvec3 l = d / std::sqrt(r2);
            // cos at the floor x cos at the emitter (both l.y) / r^2 dA = cos dOmega.
            sum += glm::dvec3(evaluateBrdf(brdf, n, v, glm::vec3(l))) * (l.y * l.y / r2);
        }
    }
    radiance = sum * (cell * cell) * glm::dvec3(s.le);
    return true;
}

TEST(ReferenceGlossy, RoughMetalFloorReflectsTheEmitterAsItsBrdfIntegratesToo) {
    const MirrorScene s = mirrorScene(0.2f);
    constexpr int kSize = 24;
    const scene::CameraView camera = scene::cameraLookAt(glm::vec3(0.0f, 0.3f, 1.2f),
            glm::vec3(0.0f, 0.0f, 0.6f), glm::radians(50.0f), 1.0f, s.scene.bounds);
    ReferenceSettings settings = referenceSettings(256, 1);
    settings.glossy = true;
    const ReferenceResult glossy = renderReference(s.scene, camera, kSize, kSize, settings);
    ASSERT_EQ(glossy.width(), kSize);
    const ReferenceResult lambert =
            renderReference(s.scene, camera, kSize, kSize, referenceSettings(64, 1));
    const double peak = double(s.le.r) * double(s.baseColor.r);
    int bright = 0, dark = 0;
    glm::dvec3 expectedSum(0.0), observedSum(0.0);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::dvec3 expected;
            if (!expectedReflection(s, camera, kSize, x, y, expected)) continue;
            const glm::vec3 observed = glossy.direct.at(x, y);
            // The pixel's value is its footprint's mean; the centre's stands for it where the
            // reflection is nearly flat: well inside the emitter's image or well outside.
            if (expected.r > 0.8 * peak) {
                ++bright;
                expectedSum += expected;
                observedSum += glm::dvec3(observed);
                // A pixel's noise is ~3% at 256 paths: four sigma.
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(observed[c], expected[c], 0.12 * expected[c])
                            << "pixel " << x << "," << y << " channel " << c;
                }
                EXPECT_LT(lambert.direct.at(x, y).r, 0.5f * observed.r)
                        << "the Lambertian floor spreads the light instead";
            } else if (expected.r < 0.01 * peak) {
                ++dark;
                EXPECT_LT(observed.r, 0.02 * peak) << "pixel " << x << "," << y;
            }
        }
    }
    // Over all of them the noise averages out: any bias of the estimator or of the BRDF's
    // sampling shows.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(observedSum[c] / expectedSum[c], 1.0, 0.015) << "channel " << c;
    }
    EXPECT_GT(bright, 10);
    EXPECT_GT(dark, 10);
}

} // namespace
} // namespace gi::reference
