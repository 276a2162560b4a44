// The sky light against the analytic answer: an open plane under a sky of radiance L receives
// E = pi L (DESIGN.md), so a Lambertian plane of albedo rho shows radiance rho L, in every
// mode: direct (the open-hemisphere term), voxel GI (every cone escapes) and atlas GI (every
// sky direction is open).
#include "GpuTest.h"

#include "scene/CameraView.h"
#include "scene/GltfLoader.h"

namespace gi::test {
namespace {

class SkyGpuTest : public GpuTest,
                   public ::testing::WithParamInterface<render::GiMode> {};

std::string modeName(render::GiMode mode) {
    return mode == render::GiMode::Direct ? "direct" : mode == render::GiMode::Voxel ? "voxel" : "atlas";
}

core::Image render(const scene::Scene& scene, render::GiMode mode, int size) {
    Settings settings;
    settings.specular = 0.0f;
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(mode, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {size, size}, render::OutputComponent::Final, profiler);
    profiler.flush();
    return renderer.readback();
}

scene::Scene planeUnderSky(const glm::vec3& radiance) {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_TRUE(scene::loadGltf(sourcePath("assets/analytic/plane_point_light.gltf"), scene, error,
            warnings)) << error;
    scene::Light sky;
    sky.type = scene::LightType::Sky;
    sky.color = radiance;
    sky.intensity = 1.0f;
    scene.lights = {sky};
    return scene;
}

TEST_P(SkyGpuTest, OpenPlaneReceivesPiL) {
    constexpr int kSize = 64;
    const glm::vec3 radiance(0.5f, 1.0f, 2.0f);
    const scene::Scene scene = planeUnderSky(radiance);
    ASSERT_FALSE(scene.cameras.empty());
    const core::Image image = render(scene, GetParam(), kSize);
    ASSERT_FALSE(image.empty());
    const float rho = scene.materials.at(0).baseColorFactor.r;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    int probes = 0;
    for (int y = 2; y < kSize; y += 4) {
        for (int x = 2; x < kSize; x += 4) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;
            const glm::vec3 observed = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                // 3%: the cones' and directions' weights sum to one exactly; what remains is
                // the half-float voxel and atlas storage. A missing pi or a cone that does
                // not escape is off by far more.
                EXPECT_NEAR(observed[c], rho * radiance[c], 0.03f * rho * radiance[c])
                        << modeName(GetParam()) << " at (" << p.x << ", " << p.z << ") channel " << c;
            }
            ++probes;
        }
    }
    EXPECT_GT(probes, 50);
}

INSTANTIATE_TEST_SUITE_P(Modes, SkyGpuTest, ::testing::Values(render::GiMode::Direct,
        render::GiMode::Voxel, render::GiMode::Atlas));

} // namespace
} // namespace gi::test
