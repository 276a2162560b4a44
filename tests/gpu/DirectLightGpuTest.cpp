// Direct light against analytic answers and golden images. The analytic probes cannot drift
// with a re-baselined image: a Lambertian plane under a point light has radiance
// L = rho/pi * I * cos(theta) / d^2 at every point (DESIGN.md conventions).
#include "GpuTest.h"
#include "ImageCompare.h"

#include "scene/CameraView.h"
#include "scene/GltfLoader.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

class DirectLightGpuTest : public GpuTest {};

TEST_F(DirectLightGpuTest, PlaneUnderPointLightMatchesInverseSquareLaw) {
    constexpr int kSize = 96;
    RenderRequest request;
    request.scenePath = "assets/analytic/plane_point_light.gltf";
    request.width = request.height = kSize;
    request.settings.specular = 0.0f;
    const core::Image image = renderScene(request);
    ASSERT_FALSE(image.empty());

    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::loadGltf(sourcePath(request.scenePath), scene, error, warnings)) << error;
    ASSERT_EQ(scene.lights.size(), 1u);
    const scene::Light& light = scene.lights[0];
    const float rho = scene.materials.at(0).baseColorFactor.r;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);

    int probes = 0;
    for (int y = 2; y < kSize; y += 6) {
        for (int x = 2; x < kSize; x += 6) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            // Stay a pixel or two away from the plane's edges, where coverage is partial.
            if (std::abs(p.x) > 0.97f || std::abs(p.z) > 0.97f) continue;
            const glm::vec3 toLight = light.position - p;
            const float d2 = glm::dot(toLight, toLight);
            const float cosTheta = toLight.y / std::sqrt(d2);
            const float expected = rho / glm::pi<float>() * light.intensity * cosTheta / d2;
            const glm::vec3 observed = image.at(x, y);
            // 1%: the bound. Both sides are float32 with the exact sample position, so
            // the real error is ~1e-6; a wrong convention (missing pi, cos, or d^2) is > 10%.
            EXPECT_NEAR(observed.r, expected, 0.01f * expected)
                    << "Probe at (" << p.x << ", " << p.y << ", " << p.z << ") pixel (" << x << ", "
                    << y << "): expected " << expected << " observed " << observed.r;
            EXPECT_FLOAT_EQ(observed.r, observed.g);
            ++probes;
        }
    }
    EXPECT_GT(probes, 100) << "the plane should fill most of the view";
}

TEST_F(DirectLightGpuTest, IndirectOutputIsZeroWithoutGi) {
    RenderRequest request;
    request.scenePath = "assets/cornell_box/cornell_box.gltf";
    request.output = render::OutputComponent::Indirect;
    const core::Image image = renderScene(request);
    ASSERT_FALSE(image.empty());
    for (float v : image.rgb) ASSERT_EQ(v, 0.0f);
}

TEST_F(DirectLightGpuTest, CornellBoxGolden) {
    RenderRequest request;
    request.scenePath = "assets/cornell_box/cornell_box.gltf";
    request.width = request.height = 256;
    const core::Image image = renderScene(request);
    ASSERT_FALSE(image.empty());
    EXPECT_TRUE(core::allFinite(image));
    const std::string failure = compareWithReference(image, "frame/cornell_direct");
    EXPECT_TRUE(failure.empty()) << failure;
}

} // namespace
} // namespace gi::test
