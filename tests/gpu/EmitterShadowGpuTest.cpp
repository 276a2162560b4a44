// An emitting surface is opaque to the other lights, as in the path tracer: a square lamp over
// a floor casts the sun's shadow under every shadow method. The ray-traced methods (bvh,
// linespace) once left every area light's triangles out of the casters, so the lamp let the
// sun through; shadow maps never did. Deep in the square's sun shadow the floor receives the
// lamp's own light only (the render with the area lights alone), and outside it the sun's
// analytic light on top of that.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"
#include "scene/EmissionLights.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

constexpr float kLampHeight = 0.6f;
constexpr float kLampHalf = 0.2f;

class EmitterShadowGpuTest : public GpuTest, public ::testing::WithParamInterface<int> {};

TEST_P(EmitterShadowGpuTest, EmittingSquareShadowsTheSun) {
    constexpr int kSize = 64;
    scene::Scene lampOnly =
            floorUnderLamp(kLampHalf, kLampHeight, {0.0f, 0.0f}, 0.5f, {0.0f, 1.8f, 1.6f});
    scene::addEmissionLights(lampOnly);
    ASSERT_FALSE(lampOnly.lights.empty());

    scene::Scene withSun = lampOnly;
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 1.0f;
    withSun.lights.push_back(sun);

    RenderRequest request;
    request.width = request.height = kSize;
    request.settings.specular = 0.0f;
    request.settings.shadow.method = GetParam();
    const core::Image lampLight = renderScene(lampOnly, request);
    const core::Image both = renderScene(withSun, request);
    ASSERT_FALSE(lampLight.empty());
    ASSERT_FALSE(both.empty());

    // The square's shadow on the floor: its centre moved along the sun to y = 0.
    const glm::vec2 shadowCentre = glm::vec2(sun.direction.x, sun.direction.z) *
                                   (kLampHeight / -sun.direction.y);
    const float sunLight = 0.5f / glm::pi<float>() * sun.intensity * -sun.direction.y;
    const scene::CameraView camera =
            scene::cameraFromScene(withSun.cameras[0], 1.0f, withSun.bounds);
    int umbraProbes = 0, litProbes = 0;
    for (int y = 1; y < kSize; y += 2) {
        for (int x = 1; x < kSize; x += 2) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.95f || std::abs(p.z) > 0.95f) continue;
            const glm::vec2 fromShadow = glm::vec2(p.x, p.z) - shadowCentre;
            const float reach = std::max(std::abs(fromShadow.x), std::abs(fromShadow.y));
            const float sunPart = both.at(x, y).g - lampLight.at(x, y).g;
            if (reach < 0.5f * kLampHalf) {
                // 3 %: the shadow maps' filter and the line space's clearance blur the edge,
                // not the middle; a lamp that lets the sun through gives all of it.
                EXPECT_NEAR(sunPart, 0.0f, 0.03f * sunLight)
                        << "probe (" << p.x << ", " << p.z << ") in the lamp's sun shadow";
                ++umbraProbes;
            } else if (reach > 2.0f * kLampHalf) {
                EXPECT_NEAR(sunPart, sunLight, 0.03f * sunLight)
                        << "probe (" << p.x << ", " << p.z << ") in the sun";
                ++litProbes;
            }
        }
    }
    EXPECT_GT(umbraProbes, 4);
    EXPECT_GT(litProbes, 100);
}

INSTANTIATE_TEST_SUITE_P(ShadowMethods, EmitterShadowGpuTest,
        ::testing::Values(SHADOW_METHOD_SHADOWMAP, SHADOW_METHOD_BVH, SHADOW_METHOD_LINESPACE),
        [](const auto& info) {
            return info.param == SHADOW_METHOD_SHADOWMAP ? "shadowmap"
                   : info.param == SHADOW_METHOD_BVH     ? "bvh"
                                                         : "linespace";
        });

} // namespace
} // namespace gi::test
