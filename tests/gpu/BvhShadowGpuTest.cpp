// shadow.method=bvh against geometry: a plate between a floor and a light shadows exactly the
// floor points whose segment to the light crosses it. With a point light the shadow is hard
// and exact per pixel; with an emitting square above the plate each floor point's visible
// share of the square is integrated numerically here and the ray estimate must match it on
// average (the rays are random; the unshadowed light they scale is exact).
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"
#include "scene/EmissionLights.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

class BvhShadowGpuTest : public GpuTest {};

constexpr float kPlateHalf = 0.2f;
constexpr float kPlateHeight = 0.5f;
constexpr int kSize = 64;

core::Image renderBvh(const scene::Scene& scene, int rays) {
    RenderRequest request;
    request.width = request.height = kSize;
    request.settings.specular = 0.0f;
    request.settings.shadow.method = SHADOW_METHOD_BVH;
    request.settings.shadow.rays = rays;
    return renderScene(scene, request);
}

// Whether the segment from floor point p to y crosses the plate.
bool plateBlocks(const glm::vec3& p, const glm::vec3& y) {
    const float t = (kPlateHeight - p.y) / (y.y - p.y);
    if (!(t > 0.0f && t < 1.0f)) return false;
    const glm::vec3 q = p + t * (y - p);
    return std::abs(q.x) < kPlateHalf && std::abs(q.z) < kPlateHalf;
}

TEST_F(BvhShadowGpuTest, PointLightShadowIsExactPerPixel) {
    scene::Scene scene = floorWithPlate(kPlateHalf, kPlateHeight);
    scene::Light light;
    light.position = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.lights = {light};
    const core::Image image = renderBvh(scene, 1);
    ASSERT_FALSE(image.empty());
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    int lit = 0, shadowed = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.95f || std::abs(p.z) > 0.95f) continue;
            // Pixels within a pixel's footprint of the shadow's edge may go either way.
            const float edge = 2.0f * kPlateHalf;
            if (std::abs(std::abs(p.x) - edge) < 0.04f || std::abs(std::abs(p.z) - edge) < 0.04f) continue;
            const glm::vec3 toLight = light.position - p;
            const float d2 = glm::dot(toLight, toLight);
            const float unshadowed = 0.5f / glm::pi<float>() * toLight.y / std::sqrt(d2) / d2;
            const bool blocked = plateBlocks(p, light.position);
            const float expected = blocked ? 0.0f : unshadowed;
            EXPECT_NEAR(image.at(x, y).r, expected, 1e-3f * unshadowed)
                    << "floor (" << p.x << ", " << p.z << ")" << (blocked ? " in shadow" : " lit");
            ++(blocked ? shadowed : lit);
        }
    }
    EXPECT_GT(lit, 100);
    EXPECT_GT(shadowed, 20);
}

TEST_F(BvhShadowGpuTest, AreaLightPenumbraMatchesVisibleShare) {
    scene::Scene scene = floorWithPlate(kPlateHalf, kPlateHeight);
    scene::Material emitter;
    emitter.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    emitter.emissiveFactor = glm::vec3(4.0f);
    scene.materials.push_back(emitter);
    constexpr float kEmitterHalf = 0.15f, kEmitterHeight = 1.0f;
    scene::Primitive top = horizontalSquare(kEmitterHalf, kEmitterHeight);
    top.indices = {0, 1, 2, 0, 2, 3};   // facing -Y
    top.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
    top.material = 2;
    addPrimitive(scene, top);
    ASSERT_GE(scene::addEmissionLights(scene).lights, 1u);
    const core::Image image = renderBvh(scene, 64);
    ASSERT_FALSE(image.empty());
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    double observedSum = 0.0, expectedSum = 0.0;
    int penumbra = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;
            // E and its visible part by the midpoint rule over the emitter (80 x 80 cells).
            constexpr int kCells = 80;
            const float cell = 2.0f * kEmitterHalf / kCells;
            double all = 0.0, visible = 0.0;
            for (int i = 0; i < kCells; ++i) {
                for (int k = 0; k < kCells; ++k) {
                    const glm::vec3 q(-kEmitterHalf + (float(i) + 0.5f) * cell, kEmitterHeight,
                            -kEmitterHalf + (float(k) + 0.5f) * cell);
                    const glm::vec3 d = q - p;
                    const float r2 = glm::dot(d, d);
                    const double f = double(d.y * d.y / (r2 * r2));
                    all += f;
                    if (!plateBlocks(p, q)) visible += f;
                }
            }
            const double share = visible / all;
            const double expected = 0.5 / glm::pi<double>() * 4.0 * visible * double(cell * cell);
            const double observed = image.at(x, y).r;
            if (share > 0.999 || share < 0.001) {
                // Fully lit or fully shadowed: no noise at all.
                EXPECT_NEAR(observed, expected, 2e-3 * expected + 1e-6)
                        << "floor (" << p.x << ", " << p.z << ") share " << share;
            } else {
                ++penumbra;
                observedSum += observed;
                expectedSum += expected;
            }
        }
    }
    ASSERT_GT(penumbra, 20);
    // 64 rays per pixel over the penumbra's pixels: the mean's noise is well under 2%.
    EXPECT_NEAR(observedSum / expectedSum, 1.0, 0.03) << penumbra << " penumbra pixels";
}

} // namespace
} // namespace gi::test
