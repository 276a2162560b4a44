// Texture-atlas GI scored against the path tracer (one bounce, the Lambertian reference) on
// the Cornell box: the area-form estimator's error must not grow as its sample count grows
// (with the light moved off the ceiling, see below); the thesis' merz2010 weighting and the
// issue's accuracy target are measured and printed.
// Each sample count is rendered with several Cranley-Patterson rotations of its sample set
// (atlas.progressive=0, atlas.rotate=1: frame k uses rotation k), so the spread of the error
// at one count is measured rather than guessed.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/Shared.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <glad/gl.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace gi::test {
namespace {

// 96x96 pixels and a 256^2 atlas keep the enabled tests near 25 s on llvmpipe (2 cores).
constexpr int kSize = 96;
constexpr int kAtlasResolution = 256;
// 128 one-bounce paths per pixel: the reference's own noise is ~2-3% of the indirect light
// (printed), far below the atlas errors compared here, and the same reference scores every
// sample count, so it cannot make one count look worse than another.
constexpr int kReferenceSpp = 128;
// Six rotations per count: enough for a standard error of the mean error (5 degrees of
// freedom), and 6 x (16 + 64 + 256 + 1024) samples x 65536 texels takes a few seconds.
constexpr int kRotations = 6;
constexpr int kSampleCounts[] = {16, 64, 256, 1024};
// The light of AtlasGpuTest.FloorMeanIsStableAsSamplesGrow: 13 cm under the ceiling instead
// of 1 cm, so no surface gets a sharp hot spot of direct light.
constexpr glm::vec3 kMidBoxLight(0.278f, 0.42f, -0.15f);

scene::Scene loadCornell(std::optional<glm::vec3> lightPosition) {
    scene::Scene scene = loadCornellBox();
    if (lightPosition) scene.lights.at(0).position = *lightPosition;
    return scene;
}

Settings atlasSettings(int samples, int estimator, int visibility) {
    Settings settings = thesisAllocation();
    settings.specular = 0.0f; // the reference is Lambertian
    settings.atlas.resolution = kAtlasResolution;
    settings.atlas.samples = samples;
    settings.atlas.estimator = estimator;
    settings.atlas.visibility = visibility;
    settings.atlas.progressive = false;
    settings.atlas.rotate = true;
    settings.atlas.cache = false; // tests never touch the user's cache directory
    return settings;
}

// The Cornell box from camera 0 (optionally with its light moved), its one-bounce reference,
// and an atlas-GI renderer whose indirect output is scored against it.
class CornellScore {
public:
    explicit CornellScore(std::optional<glm::vec3> lightPosition = std::nullopt)
            : mScene(loadCornell(lightPosition)) {
        mCamera = scene::cameraFromScene(mScene.cameras[0], 1.0f, mScene.bounds);
        ReferenceSettings reference;
        reference.spp = kReferenceSpp;
        reference.bounces = 1;
        mTruth = reference::renderReference(mScene, mCamera, kSize, kSize, reference);
        EXPECT_FALSE(mTruth.indirect.empty());
        std::string error;
        EXPECT_TRUE(mRenderer.init(mScene, atlasSettings(16, ATLAS_ESTIMATOR_AREA,
                                                   ATLAS_VISIBILITY_NONE),
                mShaders, error))
                << error;
        EXPECT_TRUE(mRenderer.setMode(render::GiMode::Atlas, error)) << error;
    }

    // Applies `settings` (restarting the rotation sequence at rotation 0), then renders
    // `rotations` frames and scores each one's indirect light.
    std::vector<reference::ImageErrors> score(const Settings& settings, int rotations) {
        std::string error;
        EXPECT_TRUE(mRenderer.setSettings(settings, error)) << error;
        std::vector<reference::ImageErrors> out;
        gl::GpuProfiler profiler;
        for (int k = 0; k < rotations; ++k) {
            mRenderer.render(mCamera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
            out.push_back(reference::measureImageError(
                    mRenderer.readback(), mTruth.indirect, mTruth.coverage));
        }
        profiler.flush();
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        return out;
    }

    double referenceNoise() const { return mTruth.noise.indirect; }

private:
    scene::Scene mScene;
    scene::CameraView mCamera;
    reference::ReferenceResult mTruth;
    gl::ShaderLibrary mShaders;
    render::FrameRenderer mRenderer;
};

struct Spread {
    double mean = 0.0;
    double standardError = 0.0; // of the mean: sample standard deviation / sqrt(count)
};

Spread relativeRmseSpread(const std::vector<reference::ImageErrors>& errors) {
    Spread s;
    const double n = double(errors.size());
    for (const reference::ImageErrors& e : errors) s.mean += e.relativeRmse / n;
    double squares = 0.0;
    for (const reference::ImageErrors& e : errors) {
        squares += (e.relativeRmse - s.mean) * (e.relativeRmse - s.mean);
    }
    s.standardError = std::sqrt(squares / (n - 1.0) / n);
    return s;
}

class AtlasReferenceGpuTest : public GpuTest {};

// Mean relative RMSE (and mean energy ratio) of area + no visibility over `rotations`
// rotations at each sample count, printed.
std::vector<Spread> areaErrorsBySamples(CornellScore& cornell, const char* label, int rotations) {
    std::vector<Spread> spread;
    for (const int samples : kSampleCounts) {
        const std::vector<reference::ImageErrors> errors = cornell.score(
                atlasSettings(samples, ATLAS_ESTIMATOR_AREA, ATLAS_VISIBILITY_NONE), rotations);
        spread.push_back(relativeRmseSpread(errors));
        double energy = 0.0;
        for (const reference::ImageErrors& e : errors) energy += e.energyRatio / rotations;
        std::printf("%s, area, no visibility, %4d samples: relative RMSE %.3f +- %.3f (mean over "
                    "%d rotations +- its standard error), energy ratio %.3f\n",
                label, samples, spread.back().mean, spread.back().standardError, rotations, energy);
    }
    return spread;
}

// The area estimator converges: its mean error over rotations does not grow as the samples
// per texel go 16 -> 64 -> 256 -> 1024. The light is moved from 1 cm under the ceiling to
// the middle of the box, as in AtlasGpuTest.FloorMeanIsStableAsSamplesGrow, so the figures
// compare with the earlier measurements (with the light at the ceiling, points spread
// uniformly over the atlas rarely hit the few cm^2 that most of the ceiling's light comes
// from; senders drawn by their power do, and CornellBoxFiguresAgainstTheReference prints
// those figures). Visibility is off, so the estimator converges to an image without the
// blocks' occlusion; up to 1024 samples its error falls towards that floor.
TEST_F(AtlasReferenceGpuTest, AreaEstimatorErrorDoesNotGrowWithSamples) {
    CornellScore cornell(kMidBoxLight);
    std::printf("reference (light mid-box): %d spp, relative noise of its indirect light %.3f\n",
            kReferenceSpp, cornell.referenceNoise());
    const std::vector<Spread> spread = areaErrorsBySamples(cornell, "light mid-box", kRotations);
    for (std::size_t i = 1; i < spread.size(); ++i) {
        // The expected error of a converging estimator does not grow with N. The measured
        // means scatter around their expectations by their standard errors; allowing three
        // standard errors of the difference makes a false alarm rare (one-sided 0.1% for
        // normal means, ~1.5% with the t-distribution of six rotations; the rotations are
        // fixed, so on one driver the outcome is deterministic) while an error that really
        // grows (a normalisation or accumulation bug) exceeds it. Measured on llvmpipe:
        // 0.80 +- 0.14, 0.43 +- 0.03, 0.27 +- 0.004, 0.22 +- 0.0004.
        const double margin =
                3.0 * std::hypot(spread[i - 1].standardError, spread[i].standardError);
        EXPECT_LE(spread[i].mean, spread[i - 1].mean + margin)
                << kSampleCounts[i - 1] << " -> " << kSampleCounts[i]
                << " samples: relative RMSE " << spread[i - 1].mean << " -> " << spread[i].mean
                << " (margin " << margin << ")";
    }
    // Where the estimators have converged, merz2010's energy ratio is its bias.
    const reference::ImageErrors merz = cornell.score(
            atlasSettings(1024, ATLAS_ESTIMATOR_MERZ2010, ATLAS_VISIBILITY_NONE), 1)[0];
    std::printf("light mid-box, merz2010, no visibility, 1024 samples: energy ratio %.3f "
                "(its bias), relative RMSE %.3f\n",
            merz.energyRatio, merz.relativeRmse);
}

// The Cornell box as it is (light 1 cm under the ceiling): the same figures, merz2010's energy
// ratio, and the issue's accuracy figures for area + voxel visibility at 1024 samples, printed
// for the record (measured on llvmpipe, area without visibility: relative RMSE 0.45, 0.42,
// 0.32, 0.28 at 16-1024 samples, energy ratio 1.09-1.10). Only finiteness is asserted: the
// target is not met (see DISABLED_AreaWithVoxelVisibilityMeetsTheIssueTarget).
TEST_F(AtlasReferenceGpuTest, CornellBoxFiguresAgainstTheReference) {
    CornellScore cornell;
    std::printf("reference: %d spp, relative noise of its indirect light %.3f\n", kReferenceSpp,
            cornell.referenceNoise());
    for (const Spread& s : areaErrorsBySamples(cornell, "Cornell box", kRotations)) {
        EXPECT_TRUE(std::isfinite(s.mean));
    }
    const reference::ImageErrors merz = cornell.score(
            atlasSettings(1024, ATLAS_ESTIMATOR_MERZ2010, ATLAS_VISIBILITY_NONE), 1)[0];
    std::printf("Cornell box, merz2010, no visibility, 1024 samples: energy ratio %.3f, "
                "relative RMSE %.3f\n",
            merz.energyRatio, merz.relativeRmse);
    const reference::ImageErrors voxel = cornell.score(
            atlasSettings(1024, ATLAS_ESTIMATOR_AREA, ATLAS_VISIBILITY_VOXEL), 1)[0];
    std::printf("Cornell box, area, voxel visibility, 1024 samples: relative RMSE %.3f (issue "
                "target <= 0.10), energy ratio %.3f (target 0.95-1.05)\n",
            voxel.relativeRmse, voxel.energyRatio);
    EXPECT_TRUE(std::isfinite(merz.relativeRmse) && std::isfinite(voxel.relativeRmse));
}

// The issue's accuracy target for the area estimator with voxel visibility, progressive to
// 1024 samples (16 rotated sets of 64): relative RMSE <= 0.10, energy ratio 0.95-1.05. The
// frame is supersampled 4x4 and box-averaged: the reference averages each pixel's footprint,
// so a pixel on an edge mixes the two surfaces there, where one sample per pixel shows one of
// them (the ceiling's edge row alone then carried 40% of the squared error). Measured on
// llvmpipe: relative RMSE 0.094, energy 0.961 (one sample per pixel: 0.134, 0.959).
TEST_F(AtlasReferenceGpuTest, AreaWithVoxelVisibilityMeetsTheIssueTarget) {
    CornellScore cornell;
    Settings settings = atlasSettings(64, ATLAS_ESTIMATOR_AREA, ATLAS_VISIBILITY_VOXEL);
    settings.atlas.progressive = true;
    settings.atlas.targetSamples = 1024;
    settings.supersample = 4;
    const std::vector<reference::ImageErrors> frames = cornell.score(settings, 16);
    const reference::ImageErrors& e = frames.back();
    std::printf("Cornell box, area + voxel visibility, progressive to 1024 samples, 4x4 "
                "supersampled: relative RMSE %.3f, energy ratio %.3f\n",
            e.relativeRmse, e.energyRatio);
    EXPECT_LE(e.relativeRmse, 0.10);
    EXPECT_GE(e.energyRatio, 0.95);
    EXPECT_LE(e.energyRatio, 1.05);
}

} // namespace
} // namespace gi::test
