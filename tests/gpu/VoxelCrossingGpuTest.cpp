// Cone tracing meets the planes its cones cross: a wall standing on a sunlit floor, in front
// of it, receives the floor's light as the path tracer gives it. Each voxel's plane offset is
// 8-bit and stochastically rounded, so a floor's neighbouring voxels disagree by a step or two;
// with a crossing slack of 0.01 voxels, cones whose axis crossed the floor where two of them
// meet passed through it, and the wall got 0.82 of its light (cone_tracing.glsl).
#include "GpuTest.h"
#include "TestScenes.h"

#include "reference/ReferenceRenderer.h"
#include "scene/CameraView.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace gi::test {
namespace {

constexpr int kSize = 64;
constexpr float kWallHalfWidth = 0.3f;
constexpr float kWallHeight = 0.4f;

// A vertical wall at z = 0 facing +Z, material 1.
scene::Primitive wallFacingPlusZ() {
    scene::Primitive p;
    p.positions = {{-kWallHalfWidth, 0.0f, 0.0f}, {kWallHalfWidth, 0.0f, 0.0f},
            {kWallHalfWidth, kWallHeight, 0.0f}, {-kWallHalfWidth, kWallHeight, 0.0f}};
    p.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    p.indices = {0, 1, 2, 0, 2, 3};   // counter-clockwise seen from +Z
    p.material = 1;
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    return p;
}

// A grey floor (half-size 1, albedo 0.5) and the wall (albedo 0.7) on it, under a sun from
// the front that lights both; the camera looks at the wall from 1.2 m.
scene::Scene wallOnSunlitFloor() {
    scene::Scene scene;
    scene::Material floor;
    floor.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    scene::Material wall;
    wall.baseColorFactor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
    scene.materials = {floor, wall};
    addPrimitive(scene, horizontalSquare(1.0f, 0.0f));
    addPrimitive(scene, wallFacingPlusZ());
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.24f, -0.56f, -0.8f));
    sun.intensity = 2.0f;
    scene.lights.push_back(sun);
    scene.cameras.push_back(lookAtCamera({0.0f, 0.2f, 1.2f}, {0.0f, 0.15f, 0.0f}, 40.0f));
    return scene;
}

// Pixels whose centre sees the wall more than a quarter of its height above the floor (the
// corner, where the floor's light comes from within a voxel or two, is another question).
std::vector<bool> upperWallPixels(const scene::Scene& scene) {
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    std::vector<bool> mask(std::size_t(kSize * kSize), false);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlane(camera, kSize, kSize, x, y, 2, 0.0f, p)) continue;
            mask[std::size_t(y * kSize + x)] = std::abs(p.x) < 0.9f * kWallHalfWidth &&
                    p.y > 0.25f * kWallHeight && p.y < 0.95f * kWallHeight;
        }
    }
    return mask;
}

class VoxelCrossingGpuTest : public GpuTest {};

TEST_F(VoxelCrossingGpuTest, AWallOnASunlitFloorReceivesTheFloorsLight) {
    const scene::Scene scene = wallOnSunlitFloor();
    const std::vector<bool> wall = upperWallPixels(scene);
    int pixels = 0;
    for (bool w : wall) pixels += w ? 1 : 0;
    ASSERT_GT(pixels, 200) << "the wall should fill much of the view";
    RenderRequest request;
    request.width = request.height = kSize;
    request.output = render::OutputComponent::Indirect;
    request.mode = render::GiMode::Voxel;
    request.settings.specular = 0.0f;
    const core::Image voxel = renderScene(scene, request);
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 256;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    const reference::ReferenceResult truth =
            reference::renderReference(scene, camera, kSize, kSize, referenceSettings);
    const double ratio = sumOverMask(voxel, wall) / sumOverMask(truth.indirect, wall);
    std::printf("the wall's indirect light over %d pixels, voxel GI / path tracer: %.3f\n",
            pixels, ratio);
    EXPECT_GT(ratio, 0.93) << "cones pass through the floor";
    EXPECT_LT(ratio, 1.07);
}

} // namespace
} // namespace gi::test
