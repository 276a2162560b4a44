// Shadow maps against geometry: a 0.4 m square occluder 0.5 m above a floor, lit from above
// by each light type. Floor points whose segment to the light crosses the occluder must be
// dark; points well outside the shadow must get the unshadowed analytic radiance.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace gi::test {
namespace {

// A floor of albedo 0.5 (floorHalf metres each side of the origin) under a square occluder
// (plateHalf) 0.5 m above it, lit by `light`, seen straight down from 2.4 m.
scene::Scene occluderScene(const scene::Light& light, float floorHalf = 1.0f,
        float plateHalf = 0.2f) {
    scene::Scene s;
    scene::Material white;
    white.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    s.materials.push_back(white);
    addPrimitive(s, horizontalSquare(floorHalf, 0.0f));
    addPrimitive(s, horizontalSquare(plateHalf, 0.5f));
    s.lights.push_back(light);
    scene::Camera camera;
    // Straight down from above the light, so the floor fills the view around the occluder.
    camera.worldFromCamera = glm::inverse(glm::lookAt(glm::vec3(0.0f, 2.4f, 0.001f),
            glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f)));
    camera.yfov = glm::radians(50.0f);
    s.cameras.push_back(camera);
    return s;
}

// A Lambertian render of `s` from its camera 0, `size` pixels a side, and that camera.
struct ProbedRender {
    core::Image image;
    scene::CameraView camera;
};

ProbedRender renderLambertian(const scene::Scene& s, int size) {
    RenderRequest request;
    request.width = request.height = size;
    request.settings.specular = 0.0f;
    return {renderScene(s, request), scene::cameraFromScene(s.cameras[0], 1.0f, s.bounds)};
}

// Calls probe(p, observed red radiance) at every third pixel of the render that shows the floor
// point p beside the occluder, no further than maxFromCenter from the floor's centre along
// either axis: points seen through the occluder show the occluder itself, not the floor.
template <typename Probe>
void forFloorProbes(const ProbedRender& render, int size, float maxFromCenter, Probe probe) {
    const float hiddenByOccluder = 0.2f * 2.4f / (2.4f - 0.5f);
    for (int y = 1; y < size; y += 3) {
        for (int x = 1; x < size; x += 3) {
            glm::vec3 p;
            if (!pixelOnPlaneY(render.camera, size, size, x, y, 0.0f, p)) continue;
            const float fromCenter = std::max(std::abs(p.x), std::abs(p.z));
            if (fromCenter < hiddenByOccluder + 0.03f || fromCenter > maxFromCenter) continue;
            probe(p, render.image.at(x, y).r);
        }
    }
}

// The Lambertian floor's unshadowed radiance at p from a point or spot light (inside its inner
// cone) or a directional light, for albedo rho.
float unshadowedRadiance(const scene::Light& light, glm::vec3 p, float rho) {
    if (light.type == scene::LightType::Directional) {
        return rho / glm::pi<float>() * light.intensity * -light.direction.y;
    }
    const glm::vec3 toLight = light.position - p;
    const float d2 = glm::dot(toLight, toLight);
    return rho / glm::pi<float>() * light.intensity * (toLight.y / std::sqrt(d2)) / d2;
}

struct ShadowCase {
    const char* name;
    scene::Light light;
    float umbraHalfSize;   // floor square |x - umbraCenterX|, |z| < this is fully occluded
    float umbraCenterX;
};

class ShadowGpuTest : public GpuTest, public ::testing::WithParamInterface<ShadowCase> {};

TEST_P(ShadowGpuTest, OccluderCastsItsShadowAndNothingElse) {
    const ShadowCase& c = GetParam();
    const scene::Scene s = occluderScene(c.light);
    constexpr int kSize = 128;
    const ProbedRender render = renderLambertian(s, kSize);
    ASSERT_FALSE(render.image.empty());

    int shadowProbes = 0, litProbes = 0;
    forFloorProbes(render, kSize, 0.95f, [&](glm::vec3 p, float observed) {
        const float r = std::max(std::abs(p.x - c.umbraCenterX), std::abs(p.z));
        if (r < c.umbraHalfSize - 0.05f) {
            // Deep in the umbra: no direct light at all. 1e-6 is float noise only.
            EXPECT_LT(observed, 1e-6f) << c.name << ": probe at (" << p.x << ", " << p.z
                                       << ") should be in shadow";
            ++shadowProbes;
        } else if (r > c.umbraHalfSize + 0.05f) {
            // Outside the penumbra of the PCF kernel (a few shadow texels wide): the
            // unshadowed value, to 1% (the analytic-plane tolerance).
            const float expected = unshadowedRadiance(c.light, p, 0.5f);
            EXPECT_NEAR(observed, expected, 0.01f * expected)
                    << c.name << ": probe at (" << p.x << ", " << p.z << ") should be lit";
            ++litProbes;
        }
    });
    EXPECT_GT(shadowProbes, 20) << c.name;
    EXPECT_GT(litProbes, 100) << c.name;
}

scene::Light pointLight() {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = {0.0f, 1.0f, 0.0f};
    return l;
}

scene::Light spotLight() {
    scene::Light l = pointLight();
    l.type = scene::LightType::Spot;
    l.direction = {0.0f, -1.0f, 0.0f};
    l.innerConeAngle = glm::radians(60.0f);   // inner cone covers the whole floor: s = 1
    l.outerConeAngle = glm::radians(75.0f);
    return l;
}

scene::Light directionalLight() {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    l.intensity = 2.0f;
    return l;
}

// Point and spot at 1 m: the 0.2 m half-size occluder at 0.5 m projects to 0.4 m on the
// floor. Parallel light at 45 degrees projects it unchanged, shifted 0.5 m along +x, so the
// shadow shows beside the occluder as seen from above.
INSTANTIATE_TEST_SUITE_P(LightTypes, ShadowGpuTest,
        ::testing::Values(ShadowCase{"point", pointLight(), 0.4f, 0.0f},
                ShadowCase{"spot", spotLight(), 0.4f, 0.0f},
                ShadowCase{"directional", directionalLight(), 0.2f, 0.5f}),
        [](const auto& info) { return std::string(info.param.name); });

// A point light (a cube map) and a sun (a 2D map) in one scene: the forward pass is compiled
// for the kinds of map the lights have (FrameSwitches::shadowMaps), so each filter must still
// run for its own light when both kinds are present. Deep in the point light's umbra only the
// sun's analytic light may arrive, and deep in the sun's shadow only the point light's.
class MixedShadowGpuTest : public GpuTest {};

TEST_F(MixedShadowGpuTest, PointAndSunShadowEachOtherInOneScene) {
    scene::Scene s = occluderScene(pointLight());
    s.lights.push_back(directionalLight());
    constexpr int kSize = 128;
    const ProbedRender render = renderLambertian(s, kSize);
    ASSERT_FALSE(render.image.empty());
    int pointUmbraProbes = 0, sunShadowProbes = 0;
    forFloorProbes(render, kSize, 1.0f, [&](glm::vec3 p, float observed) {
        const float fromCenter = std::max(std::abs(p.x), std::abs(p.z));
        const float pointLight = unshadowedRadiance(s.lights[0], p, 0.5f);
        const float sunLight = unshadowedRadiance(s.lights[1], p, 0.5f);
        // The point light's umbra (0.4 m half-size about the centre) away from the sun's
        // shadow (0.2 m half-size about x = 0.5), and the other way round.
        if (fromCenter < 0.35f && p.x < 0.25f) {
            EXPECT_NEAR(observed, sunLight, 0.01f * sunLight)
                    << "probe at (" << p.x << ", " << p.z << "): the sun's light only";
            ++pointUmbraProbes;
        } else if (std::abs(p.x - 0.5f) < 0.15f && std::abs(p.z) < 0.15f && fromCenter > 0.45f) {
            EXPECT_NEAR(observed, pointLight, 0.01f * pointLight)
                    << "probe at (" << p.x << ", " << p.z << "): the point light's only";
            ++sunShadowProbes;
        }
    });
    EXPECT_GT(pointUmbraProbes, 10);
    EXPECT_GT(sunShadowProbes, 5);
}

// A sun's map spans the whole scene, so in a large scene its texels are wide. Sponza (a 37 m
// court) lost the shadows of its arches and lit them 10 % too bright with maps of 1024
// texels: the PCF kernel and the normal offset, a few texels each, spread past small
// occluders. Here an 8 cm plate 0.5 m above a 40 m floor, under a sun at 45 degrees: the
// middle of its shadow must stay dark at the defaults (about 1 cm texels), and the floor
// around it must keep its analytic light (no acne where the offset shrank with the texel).
class SunShadowGpuTest : public GpuTest {};

TEST_F(SunShadowGpuTest, KeepsASmallOccludersUmbraInALargeScene) {
    const scene::Light sun = directionalLight();
    scene::Scene s = occluderScene(sun, 20.0f, 0.04f);
    // Straight down on the shadow, 0.5 m along +x from the plate (the sun's 45 degrees).
    s.cameras = {lookAtCamera({0.5f, 2.4f, 0.0f}, {0.5f, 0.0f, 0.0f}, 10.0f)};
    constexpr int kSize = 128;
    const auto [image, camera] = renderLambertian(s, kSize);
    ASSERT_FALSE(image.empty());
    const float lit = 0.5f / glm::pi<float>() * sun.intensity * -sun.direction.y;
    int umbraProbes = 0, litProbes = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            const float r = std::max(std::abs(p.x - 0.5f), std::abs(p.z));
            const float observed = image.at(x, y).r;
            if (r < 0.01f) {
                EXPECT_LT(observed, 0.05f * lit) << "probe at (" << p.x << ", " << p.z
                                                 << ") should be in the plate's umbra";
                ++umbraProbes;
            } else if (r > 0.12f) {
                EXPECT_NEAR(observed, lit, 0.01f * lit)
                        << "probe at (" << p.x << ", " << p.z << ") should be lit";
                ++litProbes;
            }
        }
    }
    EXPECT_GT(umbraProbes, 20);
    EXPECT_GT(litProbes, 1000);
}

} // namespace
} // namespace gi::test
