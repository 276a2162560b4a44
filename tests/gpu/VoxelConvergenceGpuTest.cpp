// Monotone convergence of voxel GI (issue #7 item 2): raising a quality knob, voxel.resolution
// 16 -> 32 -> 64 or voxel.trace_scale 0.25 -> 0.5 -> 1, must not make the indirect light
// worse against the path tracer beyond noise. Scored on the Cornell box's indirect component
// from camera 0 (96x96, Lambertian) against the one-bounce reference, by the relative RMSE
// of reference::measureImageError.
//
// One voxel frame is deterministic, but where the voxel grid happens to cut the walls moves
// its error by as much as the steps compared here (v = 32: relative RMSE 0.40-0.61 over the
// offsets below). Every setting is therefore scored with the whole scene (geometry, light
// and camera) moved by kPhases offsets of a fraction of a voxel, which changes nothing in the
// image but where the grid cuts it, and the mean over the offsets is compared. The allowed
// rise of the mean from one setting to the next is
//     3 x the reference's own noise estimate (its relative RMS Monte Carlo error, printed)
//   + 2 x the standard error of the mean paired difference over the offsets,
// the first bounding what the reference's noise can add to one score and not the other, the
// second what the choice of offsets can (the same offsets score both settings, so their
// differences are paired).
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "scene/CameraView.h"
#include "render/FrameRenderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gi::test {
namespace {

// 96x96 as in VoxelGpuTest.CornellIndirectEnergyMatchesReference; the box fills the view.
constexpr int kSize = 96;
// 1024 one-bounce paths per pixel: the reference's relative noise is ~0.5% (printed), so the
// margin's reference term stays well under the differences between settings; ~5 s, once.
constexpr int kReferenceSpp = 1024;
// Six offsets: five degrees of freedom for the spread of the paired differences.
constexpr int kPhases = 6;
// The offsets span one coarsest voxel of v = 16 (the coarsest grid compared, 0.19 m for the
// camera-centred cascade of camera 0), so they also spread over the finer grids' voxels.
constexpr float kPhaseSpan = 0.19f;

// The scene moved rigidly by `offset` (metres): the camera sees the same image.
scene::Scene shifted(const scene::Scene& base, const glm::vec3& offset) {
    scene::Scene scene = base;
    const glm::mat4 move = glm::translate(glm::mat4(1.0f), offset);
    for (scene::Instance& instance : scene.instances) {
        instance.worldFromLocal = move * instance.worldFromLocal;
    }
    for (scene::Light& light : scene.lights) light.position += offset;
    for (scene::Camera& camera : scene.cameras) camera.worldFromCamera = move * camera.worldFromCamera;
    scene.bounds.min += offset;
    scene.bounds.max += offset;
    return scene;
}

// Offset k of the 3D additive recurrence with the plastic constant's powers (Roberts' R3
// sequence): evenly spread over the cube without a lattice aligned to the voxel grid.
glm::vec3 phaseOffset(int k) {
    const glm::vec3 alpha(0.8191725f, 0.6710436f, 0.5497005f);
    return glm::fract(float(k) * alpha) * kPhaseSpan;
}

const reference::ReferenceResult& cornellTruth() {
    static const reference::ReferenceResult truth = [] {
        const scene::Scene scene = loadCornellBox();
        ReferenceSettings settings;
        settings.spp = kReferenceSpp;
        settings.bounces = 1;
        const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
        return reference::renderReference(scene, camera, kSize, kSize, settings);
    }();
    return truth;
}

// The voxel-GI indirect component of `scene` from its camera 0.
core::Image voxelIndirect(const scene::Scene& scene, const Settings& settings) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
    profiler.flush();
    return renderer.readback();
}

struct Score {
    std::vector<double> rmse, energy;   // one per offset
    double meanRmse() const { return mean(rmse); }
    double meanEnergy() const { return mean(energy); }
    static double mean(const std::vector<double>& values) {
        double sum = 0.0;
        for (double v : values) sum += v;
        return sum / double(values.size());
    }
};

Score scoreSetting(const Settings& settings) {
    const reference::ReferenceResult& truth = cornellTruth();
    const scene::Scene base = loadCornellBox();
    Score score;
    for (int k = 0; k < kPhases; ++k) {
        const core::Image image = voxelIndirect(shifted(base, phaseOffset(k)), settings);
        const reference::ImageErrors errors =
                reference::measureImageError(image, truth.indirect, truth.coverage);
        score.rmse.push_back(errors.relativeRmse);
        score.energy.push_back(errors.energyRatio);
    }
    return score;
}

std::string describe(const Score& score) {
    std::string text;
    char item[32];
    for (double r : score.rmse) {
        std::snprintf(item, sizeof item, " %.3f", r);
        text += item;
    }
    std::snprintf(item, sizeof item, " (mean %.3f)", score.meanRmse());
    return text + item;
}

// Expects the mean relative RMSE of `higher` not to exceed that of `lower` by more than the
// margin of the header; prints the numbers behind it.
void expectNoWorse(const char* knob, const char* lowerName, const Score& lower,
        const char* higherName, const Score& higher) {
    std::vector<double> difference;
    for (std::size_t k = 0; k < std::size_t(kPhases); ++k) {
        difference.push_back(higher.rmse[k] - lower.rmse[k]);
    }
    const double meanDifference = Score::mean(difference);
    double squares = 0.0;
    for (double d : difference) squares += (d - meanDifference) * (d - meanDifference);
    const double standardError = std::sqrt(squares / double(kPhases - 1) / double(kPhases));
    const double referenceNoise = cornellTruth().noise.indirect;
    const double margin = 3.0 * referenceNoise + 2.0 * standardError;
    std::printf("%s %s -> %s: relative RMSE%s ->%s; mean change %+.3f, margin %.3f "
                "(3 x reference noise %.4f + 2 x standard error %.4f)\n",
            knob, lowerName, higherName, describe(lower).c_str(), describe(higher).c_str(),
            meanDifference, margin, referenceNoise, standardError);
    EXPECT_LE(meanDifference, margin) << knob << " " << lowerName << " -> " << higherName
                                      << " raises the error beyond noise";
}

class VoxelConvergenceGpuTest : public GpuTest {};

TEST_F(VoxelConvergenceGpuTest, RaisingResolutionNeverRaisesTheError) {
    ASSERT_FALSE(cornellTruth().indirect.empty());
    std::vector<Score> scores;
    const int resolutions[] = {16, 32, 64};
    for (int v : resolutions) {
        Settings settings = thesisAllocation();
        settings.specular = 0.0f;
        settings.voxel.resolution = v;
        scores.push_back(scoreSetting(settings));
        std::printf("voxel.resolution=%d: mean energy ratio %.3f\n", v, scores.back().meanEnergy());
    }
    expectNoWorse("voxel.resolution", "16", scores[0], "32", scores[1]);
    expectNoWorse("voxel.resolution", "32", scores[1], "64", scores[2]);
    // The energy bounds, for the default resolution and the next finer one.
    for (int i : {1, 2}) {
        EXPECT_GT(scores[std::size_t(i)].meanEnergy(), 0.85) << "voxel.resolution=" << resolutions[i];
        EXPECT_LT(scores[std::size_t(i)].meanEnergy(), 1.15) << "voxel.resolution=" << resolutions[i];
    }
}

TEST_F(VoxelConvergenceGpuTest, RaisingTraceScaleNeverRaisesTheError) {
    ASSERT_FALSE(cornellTruth().indirect.empty());
    std::vector<Score> scores;
    for (float scale : {0.25f, 0.5f, 1.0f}) {
        Settings settings = thesisAllocation();
        settings.specular = 0.0f;
        settings.voxel.traceScale = scale;
        scores.push_back(scoreSetting(settings));
    }
    expectNoWorse("voxel.trace_scale", "0.25", scores[0], "0.5", scores[1]);
    expectNoWorse("voxel.trace_scale", "0.5", scores[1], "1", scores[2]);
}

} // namespace
} // namespace gi::test
