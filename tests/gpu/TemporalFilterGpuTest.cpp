// The temporal reprojection filter (gi.temporal_filter, render/TemporalFilter.h): with a
// still camera it must keep the technique's converged image (the exponential average of equal
// frames is that frame: no bias), and along a camera path it must make the indirect term
// change less from frame to frame than without it (bench/TemporalMetrics.h's measure).
#include "GpuTest.h"
#include "TestScenes.h"

#include "bench/TemporalMetrics.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "render/FrameRenderer.h"
#include "scene/Animation.h"

#include <glad/gl.h>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <utility>

namespace gi::test {
namespace {

constexpr glm::ivec2 kSize{128, 72};

class TemporalFilterGpuTest : public GpuTest {};

Settings filterSettings(bool filter) {
    Settings settings;
    settings.specular = 0.0f;
    settings.temporal.filter = filter;
    // The atlas' own filter (atlas.filter) averages each texel over its 3x3 neighbours, which
    // removes most of the texel noise a moving camera sees: along the path below the plain
    // atlas image then changes by 0.039-0.044 a frame and the temporal filter takes off 0-10 %.
    // Without it the temporal filter has the noise it is for to remove.
    settings.atlas.filter = false;
    return settings;
}

// The indirect term of `frames` frames, the camera moving by `step` each frame from `start`
// (the scene's camera if none), after `settle` unrecorded frames at the start.
std::vector<bench::CoveredFrame> renderPath(const scene::Scene& scene, render::GiMode mode,
        const Settings& settings, glm::vec3 step, int frames, int settle = 0,
        std::optional<scene::CameraView> start = std::nullopt) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(mode, error)) << error;
    scene::CameraView camera = start ? *start
                                     : scene::cameraFromScene(scene.cameras[0],
                                               float(kSize.x) / float(kSize.y), scene.bounds);
    std::vector<bench::CoveredFrame> result;
    gl::GpuProfiler profiler;
    for (int i = 0; i < settle; ++i) {
        renderer.render(camera, kSize, render::OutputComponent::Indirect, profiler);
    }
    for (int i = 0; i < frames; ++i) {
        renderer.render(camera, kSize, render::OutputComponent::Indirect, profiler);
        result.push_back({renderer.readback(), renderer.readbackCoverage()});
        camera.eye += step;
        camera.view = camera.view * glm::translate(glm::mat4(1.0f), -step);
    }
    return result;
}

// The indirect term of the scene's camera after `frames` still frames without the filter, and
// from the same renderer after `frames` more with it. One renderer sees both: voxelization
// averages its fragments in the order the rasterizer's threads deliver them, so two renderers
// of the same scene may differ by a few parts in ten thousand, more than the bias looked for.
std::pair<bench::CoveredFrame, bench::CoveredFrame> stillPlainThenFiltered(
        const scene::Scene& scene, render::GiMode mode, int frames) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, filterSettings(false), shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(mode, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(
            scene.cameras[0], float(kSize.x) / float(kSize.y), scene.bounds);
    gl::GpuProfiler profiler;
    const auto renderFrames = [&] {
        for (int i = 0; i < frames; ++i) {
            renderer.render(camera, kSize, render::OutputComponent::Indirect, profiler);
        }
        return bench::CoveredFrame{renderer.readback(), renderer.readbackCoverage()};
    };
    bench::CoveredFrame plain = renderFrames();
    EXPECT_TRUE(renderer.setSettings(filterSettings(true), error)) << error;
    bench::CoveredFrame filtered = renderFrames();
    return {std::move(plain), std::move(filtered)};
}

TEST_F(TemporalFilterGpuTest, StillCameraKeepsTheConvergedImage) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    for (render::GiMode mode : {render::GiMode::Voxel, render::GiMode::Atlas}) {
        // The atlas accumulates sample sets of 100 until 1024: still from frame 11 on. The
        // voxel trace covers a quarter of the pixels a frame (voxel.trace_reuse): whole from
        // frame 4 on.
        const int frames = mode == render::GiMode::Atlas ? 12 : 5;
        const auto [plain, filtered] = stillPlainThenFiltered(scene, mode, frames);
        // Mean |plain - filtered| over their mean level (luminance, covered pixels).
        const double difference = bench::relativeFrameChange(plain, filtered);
        std::printf("%s: still camera, filtered vs plain %.5f\n", render::giModeName(mode),
                difference);
        EXPECT_LT(difference, 1e-3) << render::giModeName(mode)
                                    << ": the filter biases a still camera's image";
    }
}

TEST_F(TemporalFilterGpuTest, ReducesTheFrameToFrameChangeAlongAPath) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    const glm::vec3 right(camera.view[0][0], camera.view[1][0], camera.view[2][0]);
    const glm::vec3 step = glm::normalize(right) * 0.005f;
    // The path starts once the atlas' progressive sums reached atlas.target_samples (1024 at
    // 100 a frame), as the bench's paths do: while they still accumulate the filter keeps no
    // history (GiOutputs::converging).
    const int settle = 11;
    for (render::GiMode mode : {render::GiMode::Voxel, render::GiMode::Atlas}) {
        const double plain = bench::meanFrameChange(
                renderPath(scene, mode, filterSettings(false), step, 6, settle));
        const double filtered = bench::meanFrameChange(
                renderPath(scene, mode, filterSettings(true), step, 6, settle));
        std::printf("%s: frame-to-frame change %.4f plain, %.4f filtered\n",
                render::giModeName(mode), plain, filtered);
        EXPECT_GT(plain, 0.0);
        EXPECT_LT(filtered, 0.9 * plain) << render::giModeName(mode);
    }
}

// The fixed plan's cascade around the Cornell box snaps to its coarsest voxel (2.99 m / 32):
// the camera crossing x = 3.5 voxels moves every level by one, and the voxel light steps
// (by about 14 %) where nothing changed. With the filter the step must fade in over frames,
// as large in no frame as a third of the step, and be gone once the fade ends: the filtered
// image then differs from the plain one by no more than on the same path short of the snap
// (where the filter only averages the motion) plus a tenth of the step.
TEST_F(TemporalFilterGpuTest, ACascadeSnapFadesInInsteadOfPopping) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    const float snapX = 3.5f * 2.99f / 32.0f;   // render.plan=fixed's coarsest voxel
    const glm::vec3 step(0.001f, 0.0f, 0.0f);
    const int before = 4, frames = 22;          // the snap on frame 4 (0-based)
    Settings plain = filterSettings(false), filtered = filterSettings(true);
    plain.plan = filtered.plan = PLAN_FIXED;
    // Plain and filtered paths from `shift` metres left of the one that crosses the snap.
    const auto paths = [&](float shift) {
        const glm::vec3 eye(snapX - (float(before) - 0.5f) * step.x - shift, 0.273f, 0.8f);
        const scene::CameraView start = scene::cameraLookAt(eye,
                eye - glm::vec3(0.0f, 0.0f, 0.8f), glm::radians(39.3f),
                float(kSize.x) / float(kSize.y), scene.bounds);
        return std::pair{renderPath(scene, render::GiMode::Voxel, plain, step, frames, 11, start),
                renderPath(scene, render::GiMode::Voxel, filtered, step, frames, 11, start)};
    };
    const auto [plainPath, filteredPath] = paths(0.0f);
    const auto [plainShort, filteredShort] = paths(0.04f);   // ends 18 mm short of the snap
    std::vector<double> plainChange, filteredChange;
    for (int i = 1; i < frames; ++i) {
        plainChange.push_back(bench::relativeFrameChange(plainPath[i - 1], plainPath[i]));
        filteredChange.push_back(bench::relativeFrameChange(filteredPath[i - 1], filteredPath[i]));
    }
    const double snap = plainChange[before - 1];
    std::vector<double> others = plainChange;
    others.erase(others.begin() + (before - 1));
    std::nth_element(others.begin(), others.begin() + others.size() / 2, others.end());
    const double largest = *std::max_element(filteredChange.begin(), filteredChange.end());
    const double left = bench::relativeFrameChange(plainPath.back(), filteredPath.back());
    const double motion = bench::relativeFrameChange(plainShort.back(), filteredShort.back());
    std::printf("snap: plain %.4f (median of the other frames %.4f), filtered largest %.4f; "
                "filtered vs plain at the end %.4f, on the path short of the snap %.4f\n",
            snap, others[others.size() / 2], largest, left, motion);
    ASSERT_GT(snap, 5.0 * others[others.size() / 2]) << "the path does not cross a snap";
    EXPECT_LT(largest, snap / 3.0) << "the snap pops through the filter";
    EXPECT_LT(left, motion + 0.1 * snap) << "the filter still holds the light from before the snap";
}

// A texture of the screen-space indirect irradiance (FrameRenderer::lastIndirect) as a frame:
// rgb its irradiance, covered where its view depth is not 0.
bench::CoveredFrame readIndirect(const gl::Texture& texture, glm::ivec2 size) {
    std::vector<float> rgba(std::size_t(size.x) * std::size_t(size.y) * 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
            rgba.data());
    bench::CoveredFrame frame{core::Image(size.x, size.y), {}};
    frame.coverage.resize(std::size_t(size.x) * std::size_t(size.y));
    for (std::size_t i = 0; i < frame.coverage.size(); ++i) {
        frame.image.set(int(i) % size.x, int(i) / size.x,
                glm::vec3(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]));
        frame.coverage[i] = rgba[i * 4 + 3] != 0.0f ? 1.0f : 0.0f;
    }
    return frame;
}

// The animated box's cube slides 2 cm a frame (0.1 s of its animation), and the light around
// it changes a little every frame: too little for the history clip to reject, so an average
// of weight gi.temporal_blend = 0.2 lags about four frames of motion behind it. While the
// geometry moves the new frame weighs gi.temporal_blend_moving (0.5): after 8 moving frames
// the filter's output must differ from its input of the same frame by less than a quarter of
// the input's median change per frame (measured 0.21: 0.0019 against 0.0092; 0.42 at the
// still blend, where the clip already holds most of the image), and by under 0.6 of what it
// does when the moving frames weigh the still blend (0.49). Input and output are one
// renderer's (lastIndirect), the screen-space irradiance the filter works on: two renderers
// voxelize in different orders, and their images differ by a few parts in a thousand (a
// plain and a filtered renderer once read 0.0023 apart against a quarter frame's 0.0022),
// which is not the filter's.
TEST_F(TemporalFilterGpuTest, TheLightAroundMovingGeometryLagsLessThanAQuarterFrame) {
    scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box_animated.gltf");
    const scene::CameraView camera =
            scene::cameraFromScene(scene.cameras[0], float(kSize.x) / float(kSize.y), scene.bounds);
    const int settle = 3, moving = 8;
    // The filter's last input and output, and the input's median change per moving frame.
    const auto lastFrames = [&](float blendMoving) {
        Settings settings = filterSettings(true);
        settings.temporal.blendMoving = blendMoving;
        gl::ShaderLibrary shaders;
        render::FrameRenderer renderer;
        std::string error;
        EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
        EXPECT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
        gl::GpuProfiler profiler;
        std::vector<bench::CoveredFrame> inputs;
        bench::CoveredFrame output;
        for (int i = 0; i <= settle + moving; ++i) {
            scene::poseScene(scene, 0.5 + 0.1 * double(std::max(i - settle, 0)));
            renderer.setPose(scene);
            renderer.render(camera, kSize, render::OutputComponent::Indirect, profiler);
            const render::FrameRenderer::IndirectImages indirect = renderer.lastIndirect();
            EXPECT_TRUE(indirect.technique && indirect.filtered &&
                        indirect.technique != indirect.filtered)
                    << "the frame has no filtered indirect light";
            if (!indirect.technique || !indirect.filtered) return std::pair{0.0, 0.0};
            inputs.push_back(readIndirect(*indirect.technique, indirect.size));
            output = readIndirect(*indirect.filtered, indirect.size);
        }
        std::vector<double> steps;
        for (int i = settle + 1; i <= settle + moving; ++i) {
            steps.push_back(bench::relativeFrameChange(inputs[i - 1], inputs[i]));
        }
        std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
        return std::pair{bench::relativeFrameChange(inputs.back(), output),
                steps[steps.size() / 2]};
    };
    const auto [lag, step] = lastFrames(Settings{}.temporal.blendMoving);
    const auto [lagStill, stepStill] = lastFrames(Settings{}.temporal.blend);
    std::printf("moving cube: filtered vs its input %.4f at the moving blend, %.4f at the still "
                "blend; the input's median change per frame %.4f\n",
            lag, lagStill, step);
    ASSERT_GT(step, 0.0) << "the cube does not move";
    EXPECT_LT(lag, 0.25 * step) << "the filter lags behind the moving geometry";
    EXPECT_LT(lag, 0.6 * lagStill) << "the moving blend does not shorten the lag";
}

} // namespace
} // namespace gi::test
