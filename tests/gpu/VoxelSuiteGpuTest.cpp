// Voxel GI at default settings against the path tracer on scenes of the accuracy suite
// (assets/scene_suite), indirect component from camera 0, 96x96, Lambertian, one bounce.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"
#include "scene/CameraView.h"

#include <cstdio>
#include <string>

namespace gi::test {
namespace {

constexpr int kSize = 96;

reference::ImageErrors voxelAgainstReference(const scene::Scene& scene, const Settings& settings) {
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
    gl::GpuProfiler profiler;
    renderer.render(camera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
    profiler.flush();
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 64;
    referenceSettings.bounces = 1;
    const reference::ReferenceResult truth =
            reference::renderReference(scene, camera, kSize, kSize, referenceSettings);
    EXPECT_FALSE(truth.indirect.empty());
    return reference::measureImageError(renderer.readback(), truth.indirect, truth.coverage);
}

class VoxelSuiteGpuTest : public GpuTest {};

// A closed white box around a point light: every wall is lit and sees only lit walls. The
// thesis' coverage propagation (the mean of 8 children) halved each wall's opacity per cascade
// level, so cones saw the walls of the coarser levels half transparent and half as bright, and
// the fixed plan kept 0.83 of the indirect energy; the most opaque axis' coverage keeps 1.00.
TEST_F(VoxelSuiteGpuTest, ClosedWhiteBoxKeepsItsIndirectEnergy) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/closed_white_box.gltf");
    for (const int plan : {PLAN_FIXED, PLAN_ADAPTIVE}) {
        Settings settings;
        settings.specular = 0.0f;
        settings.plan = plan;
        const reference::ImageErrors errors = voxelAgainstReference(scene, settings);
        std::printf("closed white box, plan %d: relative RMSE %.3f, energy ratio %.3f\n", plan,
                errors.relativeRmse, errors.energyRatio);
        EXPECT_GT(errors.energyRatio, 0.9) << "plan " << plan;
        EXPECT_LT(errors.energyRatio, 1.1) << "plan " << plan;
        EXPECT_LT(errors.relativeRmse, 0.12) << "plan " << plan;
    }
}

} // namespace
} // namespace gi::test
