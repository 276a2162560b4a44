// Texture-atlas GI on Sponza (230,831 triangles in 20,000 charts, most smaller than a texel at
// 512^2) scored against the path tracer's one-bounce indirect light: the mean-energy ratio
// stays in a stated band at the bench's base setting (1024^2, 100 samples) and at 512^2 with
// 25 samples, without visibility and with voxel visibility, and the two atlas resolutions
// agree. Regression test for atlas energy that was 0 (black) at 512^2 and swung between 0.1
// and 3.2 with the sample set's rotation at 1024^2. Skipped where Sponza is not provided.
#include "GpuTest.h"
#include "Sponza.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/Shared.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"

#include <glad/gl.h>
#include <glm/gtc/constants.hpp>

#include <cstdio>

namespace gi::test {
namespace {

// 80x45 pixels: the energy ratio is a mean over ~3,600 pixels, so the reference's 32 paths
// per pixel leave it ~1% noise (its per-pixel noise is ~25%, printed), far below the bands.
constexpr int kWidth = 80, kHeight = 45;
constexpr int kReferenceSpp = 32;

class AtlasSponzaGpuTest : public GpuTest {};

struct Case {
    int resolution, samples, visibility;
};

TEST_F(AtlasSponzaGpuTest, IndirectEnergyAgainstTheReference) {
    VOXATLAS_SPONZA_OR_SKIP(path);
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::loadGltf(path, scene, error, warnings)) << error;
    addDefaults(scene); // the documented default light, as the bench renders it
    // The bench's Sponza view: inside the arcade, looking down the atrium.
    const scene::CameraView camera = scene::cameraLookAt({0.0f, 2.0f, 14.0f},
            {0.0f, 4.0f, -10.0f}, glm::radians(60.0f), float(kWidth) / float(kHeight),
            scene.bounds);
    ReferenceSettings referenceSettings;
    referenceSettings.spp = kReferenceSpp;
    referenceSettings.bounces = 1;
    const reference::ReferenceResult truth =
            reference::renderReference(scene, camera, kWidth, kHeight, referenceSettings);
    ASSERT_FALSE(truth.indirect.empty());
    std::printf("reference: %d spp, relative noise of its indirect light %.3f\n", kReferenceSpp,
            truth.noise.indirect);

    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    Settings settings = thesisAllocation();
    settings.specular = 0.0f; // the reference is Lambertian
    settings.atlas.cache = false; // tests never touch the user's cache directory
    settings.atlas.progressive = false;
    ASSERT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    ASSERT_TRUE(renderer.setMode(render::GiMode::Atlas, error)) << error;
    auto energy = [&](const Case& c) {
        Settings s = settings;
        s.atlas.resolution = c.resolution;
        s.atlas.samples = c.samples;
        s.atlas.visibility = c.visibility;
        std::string message;
        EXPECT_TRUE(renderer.setSettings(s, message)) << message;
        gl::GpuProfiler profiler;
        renderer.render(camera, {kWidth, kHeight}, render::OutputComponent::Indirect, profiler);
        profiler.flush();
        const core::Image image = renderer.readback();
        EXPECT_TRUE(core::allFinite(image));
        const reference::ImageErrors e =
                reference::measureImageError(image, truth.indirect, truth.coverage);
        std::printf("atlas %d^2, %d samples, %s visibility: energy ratio %.3f, relative RMSE "
                    "%.3f\n",
                c.resolution, c.samples, c.visibility == ATLAS_VISIBILITY_VOXEL ? "voxel" : "no",
                e.energyRatio, e.relativeRmse);
        return e.energyRatio;
    };

    // Without visibility (the thesis' gather) the atlas converges to more light than the path
    // tracer: receivers in the arcade see the lit court through its walls and vaults.
    // Measured on llvmpipe: 1.53 at 512^2 and 1.66 at 1024^2 after 16,384 and 8,192 samples
    // (160x90), and over six rotations of one set here 1.57-1.69 (1024^2, 100 samples) and
    // 1.41-1.63 (512^2, 25 samples). The band holds that bias and the spread of one set, and
    // fails on what the atlas gave before the fix: 0 (no sender hit at 512^2), 4.0 after many
    // samples at 512^2 (sub-texel charts counted as whole texels), 0.1-3.2 at 1024^2 (one
    // sample set shared by every receiver); here 0.10 and 0.00.
    const double base = energy({1024, 100, ATLAS_VISIBILITY_NONE});
    EXPECT_GT(base, 1.3);
    EXPECT_LT(base, 2.0);
    const double coarse = energy({512, 25, ATLAS_VISIBILITY_NONE});
    EXPECT_GT(coarse, 1.3);
    EXPECT_LT(coarse, 2.0);
    // Both resolutions estimate the same integral over the same surfaces: they agree within
    // the spread of single sets (measured here: 512^2 / 1024^2 = 0.87-0.98).
    EXPECT_NEAR(coarse / base, 1.0, 0.2);

    // With the voxel occupancy as visibility the atlas comes close to the path tracer.
    // Measured on llvmpipe: 0.82 (1024^2) and 0.81 (512^2) after 2,048 samples (160x90), and
    // 0.61-0.74 over six rotations of one set of 25 here: senders are drawn by the power they
    // send, most of it in the court that the arcade does not see, so 25 samples find few of
    // the visible ones and one set falls short more often than not. The occupancy also
    // over-occludes near walls (docs/results-atlas.md); the band is wider below 1 than above.
    const double visible = energy({512, 25, ATLAS_VISIBILITY_VOXEL});
    EXPECT_GT(visible, 0.55);
    EXPECT_LT(visible, 1.2);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

} // namespace
} // namespace gi::test
