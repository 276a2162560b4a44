// Trace reuse (voxel.trace_reuse, gi/voxel/TraceReusePass.h): while the voxels' light stands
// still a frame traces one pixel of each 2x2 block. A still camera must end with the full
// trace's image, a moving one must stay close to it, and a change of light must be traced in
// full on the frame it happens.
#include "GpuTest.h"
#include "TestScenes.h"

#include "bench/TemporalMetrics.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "render/FrameRenderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace gi::test {
namespace {

constexpr glm::ivec2 kSize{128, 96};

class TraceReuseGpuTest : public GpuTest {};

Settings reuseSettings(bool reuse, bool jitter) {
    Settings settings;
    settings.specular = 0.0f;
    settings.voxel.traceReuse = reuse;
    settings.voxel.jitter = jitter;
    return settings;
}

struct Frames {
    std::vector<bench::CoveredFrame> images;
    std::vector<bool> quarter;   // the frame traced a quarter of the pixels
};

// The indirect term of `frames` frames, the camera moving by `step` each frame; the light
// dims to half before frame `dimAt` (never if negative); from frame `fullFrom` on (never if
// negative) the same renderer traces every pixel.
Frames renderPath(const scene::Scene& scene, bool reuse, glm::vec3 step, int frames,
        int dimAt = -1, bool jitter = true, int fullFrom = -1) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, reuseSettings(reuse, jitter), shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
    scene::CameraView camera = scene::cameraFromScene(scene.cameras[0],
            float(kSize.x) / float(kSize.y), scene.bounds);
    Frames result;
    gl::GpuProfiler profiler;
    for (int i = 0; i < frames; ++i) {
        if (i == fullFrom) {
            EXPECT_TRUE(renderer.setSettings(reuseSettings(false, jitter), error)) << error;
        }
        if (i == dimAt) {
            std::vector<scene::Light> lights = scene.lights;
            for (scene::Light& light : lights) light.intensity *= 0.5f;
            renderer.setLights(lights);
        }
        renderer.render(camera, kSize, render::OutputComponent::Indirect, profiler);
        result.images.push_back({renderer.readback(), renderer.readbackCoverage()});
        result.quarter.push_back(
                renderer.technique()->status().find("a quarter traced") != std::string::npos);
        camera.eye += step;
        camera.view = camera.view * glm::translate(glm::mat4(1.0f), -step);
    }
    return result;
}

TEST_F(TraceReuseGpuTest, StillCameraEndsWithTheFullTrace) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    // Six frames with reuse, then the full trace from the same renderer: the same voxels.
    // (Two renderers may differ by a few 1e-4: the voxels' running averages add in the order
    // fragments win their spinlocks.)
    const Frames frames = renderPath(scene, true, glm::vec3(0.0f), 7, -1, true, 6);
    const bench::CoveredFrame& full = frames.images.back();
    EXPECT_FALSE(frames.quarter[0]) << "the first frame has no history: it traces every pixel";
    for (int i = 1; i < 6; ++i) EXPECT_TRUE(frames.quarter[i]) << "frame " << i;
    EXPECT_FALSE(frames.quarter[6]) << "voxel.trace_reuse off traces every pixel";
    // The first frame is the full trace itself; after frames 1-4 every pixel was traced
    // again at a quarter raster (edges may rasterise differently).
    EXPECT_LT(bench::relativeFrameChange(full, frames.images[0]), 1e-3);
    const double difference = bench::relativeFrameChange(full, frames.images[5]);
    std::printf("still camera, reused vs full trace: %.5f\n", difference);
    EXPECT_LT(difference, 2e-3);
}

TEST_F(TraceReuseGpuTest, MovingCameraStaysCloseToTheFullTrace) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    const glm::vec3 right(camera.view[0][0], camera.view[1][0], camera.view[2][0]);
    const glm::vec3 step = glm::normalize(right) * 0.01f;
    const int frames = 6;
    // Without the ring's dither, which is fixed to the screen and so changes what a moving
    // camera's full trace shows from frame to frame as much as reuse could.
    const Frames full = renderPath(scene, false, step, frames, -1, false);
    const Frames reused = renderPath(scene, true, step, frames, -1, false);
    for (int i = 1; i < frames; ++i) EXPECT_TRUE(reused.quarter[i]) << "frame " << i;
    const double difference =
            bench::relativeFrameChange(full.images.back(), reused.images.back());
    // For scale: how much the full trace itself changes from one frame to the next.
    const double frameChange = bench::relativeFrameChange(full.images[frames - 2],
            full.images.back());
    std::printf("moving camera, reused vs full trace %.5f, full trace frame to frame %.5f\n",
            difference, frameChange);
    // Measured 0.0195 at this step (about 0.9 trace pixels per frame): the history is
    // filtered bilinearly at every reprojection and edges fall back to the nearest traced
    // pixel. Nearest-texel history measured 0.046 here.
    EXPECT_LT(difference, 0.03);
}

TEST_F(TraceReuseGpuTest, ChangedLightIsTracedInFullAtOnce) {
    const scene::Scene scene = loadTestScene("assets/cornell_box/cornell_box.gltf");
    const Frames full = renderPath(scene, false, glm::vec3(0.0f), 4, 3);
    const Frames reused = renderPath(scene, true, glm::vec3(0.0f), 4, 3);
    EXPECT_TRUE(reused.quarter[2]);
    EXPECT_FALSE(reused.quarter[3]) << "a frame whose light changed must trace every pixel";
    // Not bit for bit: the auto exposure of frames 1-2 saw the quarter raster's edges.
    // Reusing the old light on 3 of 4 pixels would be off by a third.
    EXPECT_LT(bench::relativeFrameChange(full.images[3], reused.images[3]), 1e-3);
}

} // namespace
} // namespace gi::test
