// shadow.method=voxel: one cone per light through the scene's voxel occupancy. It is an
// approximation, so it is held to what it must get right: under a plate lit by a point light
// the umbra is dark and the floor away from it keeps its light; on the emissive Cornell box
// its direct light stays within 15% of the exact ray-traced (BVH) light in total.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

class VoxelShadowGpuTest : public GpuTest {};

constexpr int kSize = 64;

RenderRequest directLight(int method, int size) {
    RenderRequest request;
    request.width = request.height = size;
    request.output = render::OutputComponent::Direct;
    request.settings.specular = 0.0f;
    request.settings.shadow.method = method;
    return request;
}

TEST_F(VoxelShadowGpuTest, PlateShadowsTheFloorUnderItAndNothingElse) {
    scene::Scene scene = floorWithPlate(0.2f, 0.5f);
    scene::Light light;
    light.position = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.lights = {light};

    const core::Image image = renderScene(scene, directLight(SHADOW_METHOD_VOXEL, kSize));
    ASSERT_FALSE(image.empty());
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    int umbra = 0, lit = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            const float reach = std::max(std::abs(p.x), std::abs(p.z));
            const glm::vec3 toLight = light.position - p;
            const float d2 = glm::dot(toLight, toLight);
            const float unshadowed = 0.5f / glm::pi<float>() * toLight.y / std::sqrt(d2) / d2;
            // The exact shadow is the square |x|, |z| < 0.4; the cone blurs it by a few voxels.
            if (reach < 0.25f) {
                EXPECT_LT(image.at(x, y).r, 0.2f * unshadowed) << "umbra (" << p.x << ", " << p.z << ")";
                ++umbra;
            } else if (reach > 0.6f && reach < 0.95f) {
                EXPECT_GT(image.at(x, y).r, 0.9f * unshadowed) << "lit (" << p.x << ", " << p.z << ")";
                ++lit;
            }
        }
    }
    EXPECT_GT(umbra, 20);
    EXPECT_GT(lit, 200);
}

TEST_F(VoxelShadowGpuTest, EmissiveCornellBoxKeepsTheRayTracedEnergy) {
    RenderRequest cones = directLight(SHADOW_METHOD_VOXEL, 48), rays = directLight(SHADOW_METHOD_BVH, 48);
    cones.scenePath = rays.scenePath = "assets/cornell_box/cornell_box_emissive.gltf";
    const core::Image cone = renderScene(cones);
    const core::Image ray = renderScene(rays);
    ASSERT_EQ(cone.rgb.size(), ray.rgb.size());
    double coneSum = 0.0, raySum = 0.0;
    for (std::size_t i = 0; i < cone.rgb.size(); ++i) {
        // The panel itself (radiance far above any lit surface) is alike in both.
        if (ray.rgb[i] > 2.0f) continue;
        coneSum += cone.rgb[i];
        raySum += ray.rgb[i];
    }
    ASSERT_GT(raySum, 0.0);
    EXPECT_NEAR(coneSum / raySum, 1.0, 0.15);
}

} // namespace
} // namespace gi::test
