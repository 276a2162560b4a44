// Further bounces of indirect light (gi.bounces) in voxel and atlas GI, and vpl.bounces in VPL
// GI, on the closed white box (assets/scene_suite): a point light in a closed 2 m box of albedo 0.8, where every
// bounce lands on the walls again. Mean over the walls, bounce k adds rho^k of the direct
// irradiance, so two bounces hold 1 + rho = 1.8 times the indirect light of one (the camera
// sees part of the walls, and the higher bounces spread more evenly than the first, so a
// view's ratio is near that, not exactly it), and the path tracer with the same two
// bounces is the exact answer.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"
#include "render/OutputCatalog.h"
#include "scene/CameraView.h"

#include <cstdio>
#include <string>

namespace gi::test {
namespace {

constexpr int kSize = 64;

core::Image indirect(const scene::Scene& scene, const Settings& settings, render::GiMode mode,
        int frames) {
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(mode, error)) << error;
    gl::GpuProfiler profiler;
    for (int i = 0; i < frames; ++i) {
        renderer.render(camera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
    }
    profiler.flush();
    return renderer.readback();
}

double mean(const core::Image& image) {
    double sum = 0.0;
    for (float value : image.rgb) sum += double(value);
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

class BounceGpuTest : public GpuTest {
protected:
    // One and two bounces of `mode`: the second near 1 + rho times the first, and within 10%
    // of the path tracer's two bounces.
    void checkSecondBounce(render::GiMode mode, Settings settings, int frames) {
        const scene::Scene scene = loadTestScene("assets/scene_suite/closed_white_box.gltf");
        settings.specular = 0.0f;
        settings.giBounces = 1;
        settings.vpl.bounces = 1;
        const core::Image one = indirect(scene, settings, mode, frames);
        settings.giBounces = 2;
        settings.vpl.bounces = 2;
        const core::Image two = indirect(scene, settings, mode, frames);
        ReferenceSettings referenceSettings;
        referenceSettings.spp = 32;
        referenceSettings.bounces = 2;
        const scene::CameraView camera =
                scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
        const reference::ReferenceResult truth =
                reference::renderReference(scene, camera, kSize, kSize, referenceSettings);
        const reference::ImageErrors errors =
                reference::measureImageError(two, truth.indirect, truth.coverage);
        const double ratio = mean(two) / mean(one);
        std::printf("%s: two bounces / one %.3f (1 + rho = 1.8), energy against two path-traced "
                    "bounces %.3f, relative RMSE %.3f\n",
                render::giModeName(mode), ratio, errors.energyRatio, errors.relativeRmse);
        EXPECT_GT(ratio, 1.65);
        EXPECT_LT(ratio, 1.95);
        EXPECT_GT(errors.energyRatio, 0.9);
        EXPECT_LT(errors.energyRatio, 1.1);
    }
};

TEST_F(BounceGpuTest, VoxelSecondBounceInTheClosedWhiteBox) {
    checkSecondBounce(render::GiMode::Voxel, Settings{}, 1);
}

TEST_F(BounceGpuTest, AtlasSecondGatherInTheClosedWhiteBox) {
    Settings settings;
    settings.atlas.resolution = 256;
    settings.atlas.samples = 64;
    settings.atlas.cache = false;
    settings.plan = PLAN_FIXED;
    checkSecondBounce(render::GiMode::Atlas, settings, 8);
}

TEST_F(BounceGpuTest, VplSecondGenerationInTheClosedWhiteBox) {
    checkSecondBounce(render::GiMode::Vpl, Settings{}, 1);
}

} // namespace
} // namespace gi::test
