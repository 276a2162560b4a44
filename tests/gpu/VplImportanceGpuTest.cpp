// VPLs drawn by the view's importance (vpl.importance, the default): where most of a scene's
// reflected light cannot reach what the camera sees (the open-front box's sunlit ground
// outside), the draw by flux alone spends most VPLs there; the importance draw puts them where
// the view receives their light, and is drawn anew when the camera moves.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"
#include "scene/CameraView.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <string>

namespace gi::test {
namespace {

constexpr int kSize = 96;

Settings vplSettings(bool importance) {
    Settings settings;
    settings.specular = 0.0f;   // the reference is Lambertian
    settings.vpl.importance = importance;
    return settings;
}

class VplImportanceGpuTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (!mContext) return;
        mScene = loadTestScene("assets/scene_suite/cornell_open_front_sun.gltf");
        mCamera = scene::cameraFromScene(mScene.cameras[0], 1.0f, mScene.bounds);
    }

    void render(render::FrameRenderer& renderer, const scene::CameraView& camera) {
        gl::GpuProfiler profiler;
        renderer.render(camera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
        profiler.flush();
    }

    bool init(render::FrameRenderer& renderer, const Settings& settings) {
        std::string error;
        const bool ok = renderer.init(mScene, settings, mShaders, error) &&
                        renderer.setMode(render::GiMode::Vpl, error);
        EXPECT_TRUE(ok) << error;
        return ok;
    }

    scene::Scene mScene;
    scene::CameraView mCamera;
    gl::ShaderLibrary mShaders;
};

// Measured on llvmpipe at this size against 256 spp: 0.229 with the importance draw, 0.336 by
// flux alone (energy 0.926 and 0.931).
TEST_F(VplImportanceGpuTest, TheOpenFrontBoxScoresCloserToThePathTracer) {
    if (!mContext) GTEST_SKIP();
    ReferenceSettings reference;
    reference.spp = 256;
    reference.bounces = 1;
    const reference::ReferenceResult truth =
            reference::renderReference(mScene, mCamera, kSize, kSize, reference);
    reference::ImageErrors errors[2];
    for (const bool importance : {false, true}) {
        render::FrameRenderer renderer;
        if (!init(renderer, vplSettings(importance))) return;
        render(renderer, mCamera);
        errors[importance] = reference::measureImageError(renderer.readback(), truth.indirect,
                truth.coverage);
    }
    std::printf("open-front box %dx%d: by flux %.3f / %.3f, by importance %.3f / %.3f "
                "(reference noise %.3f)\n",
            kSize, kSize, errors[0].relativeRmse, errors[0].energyRatio, errors[1].relativeRmse,
            errors[1].energyRatio, truth.noise.indirect);
    EXPECT_LT(errors[1].relativeRmse, errors[0].relativeRmse - 0.04);
    EXPECT_GT(errors[1].energyRatio, 0.9);
    EXPECT_LT(errors[1].energyRatio, 1.1);
}

// A small step keeps the VPLs (the importance only says where to draw them, so VPLs drawn for
// a nearby view stay unbiased, and redrawing each frame would make them flicker); a step of
// more than 5 % of the scene's diagonal (3.7 m here) draws them anew, the flux draw never.
TEST_F(VplImportanceGpuTest, AMovedCameraRedrawsTheVplsOnlyWhenTheirDrawFollowsTheView) {
    if (!mContext) GTEST_SKIP();
    scene::CameraView step = mCamera, stride = mCamera;
    step.eye += glm::vec3(0.02f, 0.0f, 0.0f);
    step.view = glm::translate(mCamera.view, glm::vec3(-0.02f, 0.0f, 0.0f));
    stride.eye += glm::vec3(0.5f, 0.0f, 0.0f);
    stride.view = glm::translate(mCamera.view, glm::vec3(-0.5f, 0.0f, 0.0f));
    for (const bool importance : {false, true}) {
        render::FrameRenderer renderer;
        if (!init(renderer, vplSettings(importance))) return;
        render(renderer, mCamera);
        render(renderer, mCamera);
        ASSERT_TRUE(renderer.vplReport().has_value());
        EXPECT_EQ(renderer.vplReport()->resamples, 1) << "a still camera keeps its VPLs";
        render(renderer, step);
        EXPECT_EQ(renderer.vplReport()->resamples, 1) << "a 2 cm step keeps them";
        render(renderer, stride);
        EXPECT_EQ(renderer.vplReport()->resamples, importance ? 2 : 1) << importance;
    }
}

} // namespace
} // namespace gi::test
