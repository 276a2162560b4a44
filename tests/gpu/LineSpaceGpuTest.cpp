// shadow.method=linespace against geometry and against shadow.method=bvh. The line space
// over-occludes by construction: a leaf voxel counts as solid when a triangle touches it, and
// a ray counts as blocked when its shaft (all lines between two sub-faces of a node one level
// above the leaves) meets such a voxel. Both widen a shadow by at most about two leaf voxels
// at the occluder, which a point light projects onto the floor scaled by (light height) /
// (light height - occluder height). Away from that band the hard shadow is exact.
#include "GpuTest.h"
#include "TestScenes.h"

#include "reference/ImageMetrics.h"
#include "render/LineSpaceLayout.h"
#include "scene/CameraView.h"
#include "scene/EmissionLights.h"
#include "scene/GltfLoader.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

class LineSpaceGpuTest : public GpuTest {};

constexpr float kPlateHalf = 0.2f;
constexpr float kPlateHeight = 0.5f;
constexpr int kSize = 64;

struct Rendered {
    core::Image image;
    std::vector<float> coverage;
    render::LineSpaceStats stats;
};

Rendered renderWith(const scene::Scene& scene, int method, int rays, int size) {
    Settings settings;
    settings.specular = 0.0f;
    settings.shadow.method = method;
    settings.shadow.rays = rays;
    settings.lineSpace.n = 4;
    settings.lineSpace.depth = 3;
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {size, size}, render::OutputComponent::Final, profiler);
    profiler.flush();
    return {renderer.readback(), renderer.readbackCoverage(), renderer.lineSpaceStats()};
}

bool plateBlocks(const glm::vec3& p, const glm::vec3& y) {
    const float t = (kPlateHeight - p.y) / (y.y - p.y);
    if (!(t > 0.0f && t < 1.0f)) return false;
    const glm::vec3 q = p + t * (y - p);
    return std::abs(q.x) < kPlateHalf && std::abs(q.z) < kPlateHalf;
}

TEST_F(LineSpaceGpuTest, PointLightShadowIsExactAwayFromItsEdge) {
    scene::Scene scene = floorWithPlate(kPlateHalf, kPlateHeight);
    scene::Light light;
    light.position = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.lights = {light};
    const Rendered result = renderWith(scene, SHADOW_METHOD_LINESPACE, 1, kSize);
    ASSERT_FALSE(result.image.empty());
    EXPECT_GT(result.stats.nodes, 0u);
    const float leaf = render::lineSpaceLayout(scene.bounds, 4, 3).leafSize();
    // Two leaf voxels at the plate, projected from the light onto the floor.
    const float band = 2.0f * leaf * light.position.y / (light.position.y - kPlateHeight);
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    int lit = 0, shadowed = 0, widened = 0, inBand = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.95f || std::abs(p.z) > 0.95f) continue;
            const glm::vec3 toLight = light.position - p;
            const float d2 = glm::dot(toLight, toLight);
            const float unshadowed = 0.5f / glm::pi<float>() * toLight.y / std::sqrt(d2) / d2;
            const bool blocked = plateBlocks(p, light.position);
            const float observed = result.image.at(x, y).r;
            // Distance outside the shadow's square (edge at twice the plate's half-size).
            const float edge = 2.0f * kPlateHalf;
            const float outside = std::max(std::abs(p.x), std::abs(p.z)) - edge;
            if (std::abs(outside) < band + 0.04f) {
                // Near the edge: either lit or shadowed, never lit inside the shadow.
                ++inBand;
                if (blocked) EXPECT_NEAR(observed, 0.0f, 1e-3f * unshadowed);
                if (!blocked && observed < 0.5f * unshadowed) ++widened;
                continue;
            }
            const float expected = blocked ? 0.0f : unshadowed;
            EXPECT_NEAR(observed, expected, 1e-3f * unshadowed)
                    << "floor (" << p.x << ", " << p.z << ")" << (blocked ? " in shadow" : " lit");
            ++(blocked ? shadowed : lit);
        }
    }
    EXPECT_GT(lit, 100);
    EXPECT_GT(shadowed, 20);
    std::printf("leaf %.4f m, band %.4f m: %d of %d pixels near the edge shadowed though lit\n", leaf,
            band, widened, inBand);
}

TEST_F(LineSpaceGpuTest, EmissiveCornellBoxMatchesBvh) {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::loadGltf(sourcePath("assets/cornell_box/cornell_box_emissive.gltf"), scene,
            error, warnings)) << error;
    ASSERT_GE(scene::addEmissionLights(scene).lights, 1u);
    const Rendered bvh = renderWith(scene, SHADOW_METHOD_BVH, 25, 96);
    const Rendered lineSpace = renderWith(scene, SHADOW_METHOD_LINESPACE, 25, 96);
    ASSERT_FALSE(bvh.image.empty());
    ASSERT_FALSE(lineSpace.image.empty());
    const reference::ImageErrors errors =
            reference::measureImageError(lineSpace.image, bvh.image, bvh.coverage);
    std::printf("LS(4,3) against bvh, 25 rays: relative RMSE %.4f, energy %.4f over %zu pixels\n",
            errors.relativeRmse, errors.energyRatio, errors.pixels);
    EXPECT_GT(errors.pixels, 1000u);
    EXPECT_LT(errors.relativeRmse, 0.05);
    // Over-occlusion only darkens; the skipped start node and the clearance may lighten a little.
    EXPECT_GT(errors.energyRatio, 0.95);
    EXPECT_LT(errors.energyRatio, 1.01);
}

} // namespace
} // namespace gi::test
