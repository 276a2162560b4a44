// Static caching in voxel GI (voxel.cache, gi/voxel/VoxelizationManager.h): work whose inputs
// did not change is kept, and the kept path must render what the full path renders.
//   - a static scene under a still camera voxelizes, injects and propagates once;
//   - a camera-centred cascade is redone when its snapped placement moves, not before;
//   - new lights are injected again;
//   - a scene with an animated cube voxelizes its static part once and the cube every frame
//     it moved, and matches a renderer that redoes everything (voxel.cache=0) pose after pose.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gi/voxel/VoxelizationManager.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "render/FrameRenderer.h"
#include "scene/Animation.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace gi::test {
namespace {

constexpr int kSize = 64;

scene::CameraView cameraOf(const scene::Scene& scene) {
    return scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
}

// Mean |a - b| over the mean |b| of every channel.
double relativeDifference(const core::Image& a, const core::Image& b) {
    EXPECT_EQ(a.rgb.size(), b.rgb.size());
    double diff = 0.0, total = 0.0;
    for (std::size_t i = 0; i < std::min(a.rgb.size(), b.rgb.size()); ++i) {
        diff += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
        total += std::abs(double(b.rgb[i]));
    }
    return total > 0.0 ? diff / total : diff;
}

double mean(const core::Image& image) {
    double sum = 0.0;
    for (const float value : image.rgb) sum += double(value);
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

class Renderer {
public:
    Renderer(const scene::Scene& scene, Settings settings) {
        std::string error;
        EXPECT_TRUE(mRenderer.init(scene, settings, mShaders, error)) << error;
        EXPECT_TRUE(mRenderer.setMode(render::GiMode::Voxel, error)) << error;
    }
    core::Image frame(const scene::CameraView& camera,
            render::OutputComponent output = render::OutputComponent::Indirect) {
        gl::GpuProfiler profiler;
        mRenderer.render(camera, {kSize, kSize}, output, profiler);
        profiler.flush();
        return mRenderer.readback();
    }
    std::uint64_t reused() const {
        const auto* voxels = dynamic_cast<const voxel::VoxelizationManager*>(mRenderer.technique());
        EXPECT_NE(voxels, nullptr);
        return voxels ? voxels->reusedFrames() : 0;
    }
    render::FrameRenderer& renderer() { return mRenderer; }

private:
    gl::ShaderLibrary mShaders;
    render::FrameRenderer mRenderer;
};

Settings withCache(bool cache) {
    Settings settings = thesisAllocation();
    settings.specular = 0.0f;
    settings.voxel.cache = cache;
    // Each frame is compared with a fresh renderer's: no history blended in.
    settings.temporal.filter = false;
    return settings;
}

class StaticCachingGpuTest : public GpuTest {};

TEST_F(StaticCachingGpuTest, StillCameraReusesTheVoxelsAndMatchesTheFullPath) {
    const scene::Scene box = loadCornellBox();
    const scene::CameraView camera = cameraOf(box);
    Renderer cached(box, withCache(true)), full(box, withCache(false));
    core::Image kept, redone;
    for (int i = 0; i < 3; ++i) {
        kept = cached.frame(camera);
        redone = full.frame(camera);
    }
    EXPECT_EQ(cached.reused(), 2u) << "frames 2 and 3 only trace cones";
    EXPECT_EQ(full.reused(), 0u);
    ASSERT_GT(mean(redone), 0.0);
    // The full path's third frame differs from its first only by the stochastic rounding of
    // the voxel averages (lock order); the kept first frame must match it as closely.
    EXPECT_LT(relativeDifference(kept, redone), 0.01);
}

TEST_F(StaticCachingGpuTest, CascadeIsRedoneWhenItsPlacementMovesAndLightsChange) {
    const scene::Scene box = loadCornellBox();
    Renderer cached(box, withCache(true)), full(box, withCache(false));
    scene::CameraView camera = cameraOf(box);
    // Both size their cascade from this first camera (voxel.extent=0).
    (void)cached.frame(camera);
    (void)full.frame(camera);
    // Well under a coarsest voxel (the snap): the cascade stays where it is.
    camera.eye += glm::vec3(1e-4f, 0.0f, 0.0f);
    (void)cached.frame(camera);
    EXPECT_EQ(cached.reused(), 1u);
    // Half a metre: every level moves, so the voxels are redone for the new placement.
    camera.eye += glm::vec3(0.0f, 0.0f, 0.5f);
    const core::Image moved = cached.frame(camera);
    EXPECT_EQ(cached.reused(), 1u);
    EXPECT_LT(relativeDifference(moved, full.frame(camera)), 0.01);
    // Twice the light: injected again, twice the indirect light.
    std::vector<scene::Light> brighter = box.lights;
    for (scene::Light& light : brighter) light.intensity *= 2.0f;
    cached.renderer().setLights(brighter);
    const core::Image lit = cached.frame(camera);
    EXPECT_EQ(cached.reused(), 1u);
    EXPECT_NEAR(mean(lit) / mean(moved), 2.0, 0.04);
}

// Isotropic and anisotropic voxels alike: the cache keeps the anisotropic voxels' directional
// copy too (before, anisotropic voxels revoxelized the whole scene every frame the cube moved).
TEST_F(StaticCachingGpuTest, AnimatedCubeIsRevoxelizedOnTopOfTheKeptStaticPart) {
    for (const bool anisotropic : {false, true}) {
        SCOPED_TRACE(anisotropic ? "anisotropic voxels" : "isotropic voxels");
        scene::Scene moving = loadTestScene("assets/cornell_box/cornell_box_animated.gltf");
        const scene::CameraView camera = cameraOf(moving);
        Settings withStatic = withCache(true), redoAll = withCache(false);
        withStatic.voxel.anisotropic = redoAll.voxel.anisotropic = anisotropic;
        Renderer cached(moving, withStatic), full(moving, redoAll);
        double worst = 0.0;
        for (const double seconds : {0.0, 0.5, 1.0, 2.0}) {
            scene::poseScene(moving, seconds);
            cached.renderer().setPose(moving);
            full.renderer().setPose(moving);
            const core::Image a = cached.frame(camera, render::OutputComponent::Final);
            const core::Image b = full.frame(camera, render::OutputComponent::Final);
            worst = std::max(worst, relativeDifference(a, b));
        }
        EXPECT_EQ(cached.reused(), 0u) << "moving geometry is voxelized and lit every frame";
        EXPECT_LT(worst, 0.01) << "worst mean relative difference over the poses";
        // Paused: the cube did not move since the last frame, so nothing is redone.
        (void)cached.frame(camera, render::OutputComponent::Final);
        EXPECT_EQ(cached.reused(), 1u) << "a paused animation is a static scene";
        std::size_t staticBytes = 0, directionalBytes = 0;
        for (const gl::MemoryItem& item : cached.renderer().memory()) {
            if (item.name.rfind("voxel/static/", 0) == 0) staticBytes += item.bytes;
            if (item.name == "voxel/static/directional") directionalBytes += item.bytes;
        }
        EXPECT_GT(staticBytes, 0u);
        EXPECT_EQ(directionalBytes > 0, anisotropic) << "the directional copy, kept only for "
                                                        "anisotropic voxels";
        for (const gl::MemoryItem& item : full.renderer().memory()) {
            EXPECT_NE(item.name.rfind("voxel/static/", 0), 0u) << item.name << " without voxel.cache";
        }
    }
}

} // namespace
} // namespace gi::test
