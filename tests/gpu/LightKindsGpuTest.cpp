// The forward pass is compiled for the kinds of light the scene has (FrameSwitches::lightKinds,
// lighting.glsl: lightsOfKind), so the code of every kind present must still run, alone and
// beside the others. A floor lit by each kind of light (point, spot, sun, sky and an emitting
// square's area lights) must receive, with all of them at once, the sum of what each kind gives
// it alone; and each kind alone must light it. Direct light only, under shadow maps and under
// shadow rays, whose visibility code also branches on the kind.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"
#include "scene/EmissionLights.h"

#include <map>

namespace gi::test {
namespace {

// One light of every kind but the area lights, which addEmissionLights makes of the square.
std::vector<scene::Light> punctualAndDistantLights() {
    scene::Light point, spot, sun, sky;
    point.type = scene::LightType::Point;
    point.position = {0.6f, 0.8f, 0.3f};
    point.intensity = 0.5f;
    spot.type = scene::LightType::Spot;
    spot.position = {-0.5f, 0.9f, 0.2f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = 0.8f;
    spot.outerConeAngle = 0.6f;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 0.7f;
    sky.type = scene::LightType::Sky;
    sky.color = glm::vec3(0.05f, 0.06f, 0.08f);
    return {point, spot, sun, sky};
}

class LightKindsGpuTest : public GpuTest, public ::testing::WithParamInterface<int> {};

TEST_P(LightKindsGpuTest, EachKindLightsTheFloorAloneAndAmongTheOthers) {
    constexpr int kSize = 64;
    // A small lamp over one corner: no light of punctualAndDistantLights() casts its shadow
    // into the middle of the floor, which the test probes (its shadows are
    // EmitterShadowGpuTest's matter).
    scene::Scene scene = floorUnderLamp(0.15f, 0.6f, {-0.7f, -0.7f}, 1.5f, {0.0f, 1.6f, 1.8f});
    scene::addEmissionLights(scene);
    ASSERT_FALSE(scene.lights.empty());
    for (const scene::Light& light : punctualAndDistantLights()) scene.lights.push_back(light);

    RenderRequest request;
    request.width = request.height = kSize;
    request.settings.specular = 0.0f;
    request.settings.shadow.method = GetParam();
    const core::Image all = renderScene(scene, request);
    ASSERT_FALSE(all.empty());

    std::map<scene::LightType, core::Image> alone;
    for (const scene::Light& light : scene.lights) {
        if (alone.contains(light.type)) continue;
        scene::Scene one = scene;
        one.lights.clear();
        for (const scene::Light& l : scene.lights) {
            if (l.type == light.type) one.lights.push_back(l);
        }
        alone[light.type] = renderScene(one, request);
        ASSERT_FALSE(alone[light.type].empty());
    }
    ASSERT_EQ(alone.size(), 5u) << "point, spot, directional, sky and area";

    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    int probes = 0;
    std::map<scene::LightType, double> lightFrom;
    for (int y = 1; y < kSize; y += 3) {
        for (int x = 1; x < kSize; x += 3) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.45f || std::abs(p.z) > 0.45f) continue;
            float sum = 0.0f;
            for (const auto& [type, image] : alone) {
                sum += image.at(x, y).g;
                lightFrom[type] += image.at(x, y).g;
            }
            // 1 %: the images are float16 radiance; a kind dropped from the mix is its whole
            // share, several percent or more wherever it shines.
            EXPECT_NEAR(all.at(x, y).g, sum, 0.01f * sum + 1e-5f)
                    << "probe (" << p.x << ", " << p.z << ")";
            ++probes;
        }
    }
    EXPECT_GT(probes, 40);
    for (const auto& [type, light] : lightFrom) {
        EXPECT_GT(light / probes, 1e-3)
                << "light kind " << int(type) << " alone left the floor dark";
    }
}

INSTANTIATE_TEST_SUITE_P(ShadowMethods, LightKindsGpuTest,
        ::testing::Values(SHADOW_METHOD_SHADOWMAP, SHADOW_METHOD_BVH),
        [](const auto& info) {
            return info.param == SHADOW_METHOD_SHADOWMAP ? "shadowmap" : "bvh";
        });

} // namespace
} // namespace gi::test
