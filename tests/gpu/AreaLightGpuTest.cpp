// Area lights (emissive surfaces, scene/EmissionLights.h) against the form factor: a floor
// under an emitting square receives E(p) = L x the integral of cos(theta_p) cos(theta_y) / r^2
// over the square, which the forward pass computes exactly per triangle (lighting.glsl). The
// expected values are integrated numerically here, independently of the shader's formula.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"
#include "scene/EmissionLights.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

class AreaLightGpuTest : public GpuTest {};

constexpr float kEmitterHeight = 0.5f;
constexpr float kHalfSize = 0.5f;

// A grey floor square and an emitting square of the same size above it, facing down.
scene::Scene floorUnderEmitter(const glm::vec3& radiance) {
    scene::Scene scene;
    scene::Material grey, emitter;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    emitter.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    emitter.emissiveFactor = radiance;
    scene.materials = {grey, emitter};
    addPrimitive(scene, horizontalSquare(kHalfSize, 0.0f));
    scene::Primitive top = horizontalSquare(kHalfSize, kEmitterHeight);
    top.indices = {0, 1, 2, 0, 2, 3}; // facing -Y
    top.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
    top.material = 1;
    addPrimitive(scene, top);
    scene.cameras.push_back(lookAtCamera({0.0f, 0.2f, 1.3f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    return scene;
}

// Irradiance per unit radiance at floor point p, by the midpoint rule on a 400 x 400 grid.
double formFactorIntegral(const glm::vec3& p) {
    constexpr int kCells = 400;
    const double cell = 2.0 * kHalfSize / kCells;
    double sum = 0.0;
    for (int i = 0; i < kCells; ++i) {
        for (int k = 0; k < kCells; ++k) {
            const glm::dvec3 y(-kHalfSize + (i + 0.5) * cell, kEmitterHeight, -kHalfSize + (k + 0.5) * cell);
            const glm::dvec3 d = y - glm::dvec3(p);
            const double r2 = glm::dot(d, d);
            const double cosP = d.y / std::sqrt(r2), cosY = d.y / std::sqrt(r2);
            sum += cosP * cosY / r2 * cell * cell;
        }
    }
    return sum;
}

TEST_F(AreaLightGpuTest, FloorUnderEmitterMatchesFormFactor) {
    constexpr int kSize = 64;
    const glm::vec3 radiance(2.0f, 1.0f, 0.5f);
    scene::Scene scene = floorUnderEmitter(radiance);
    const scene::EmissionLightsReport report = scene::addEmissionLights(scene);
    // The square spans more than a quarter of the scene's diagonal: its two triangles are
    // two lights, whose irradiance adds up to the square's.
    EXPECT_EQ(report.lightTriangles, 2u);
    ASSERT_EQ(scene.lights.size(), report.lights);
    for (const scene::Light& light : scene.lights) EXPECT_EQ(light.type, scene::LightType::Area);

    Settings settings;
    settings.specular = 0.0f;
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {kSize, kSize}, render::OutputComponent::Final, profiler);
    profiler.flush();
    const core::Image image = renderer.readback();
    ASSERT_FALSE(image.empty());

    // At the centre the integral is known in closed form (point-to-parallel-square form
    // factor x pi): 4 (1/sqrt 2) atan(1/sqrt 2) = 1.7408 per unit radiance. It checks the
    // numerical integral the probes use.
    EXPECT_NEAR(formFactorIntegral(glm::vec3(0.0f)), 1.7408, 1e-3);
    const float rho = 0.5f;
    int probes = 0;
    for (int y = 1; y < kSize; y += 2) {
        for (int x = 1; x < kSize; x += 2) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.45f || std::abs(p.z) > 0.45f) continue;
            const double e = formFactorIntegral(p);
            const glm::vec3 observed = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double expected = rho / glm::pi<double>() * radiance[c] * e;
                // 0.5%: the shader's integral is exact up to float rounding; a missing clip,
                // side or pi is off by far more.
                EXPECT_NEAR(observed[c], expected, 0.005 * expected)
                        << "probe (" << p.x << ", " << p.z << ") channel " << c;
            }
            ++probes;
        }
    }
    EXPECT_GT(probes, 30);
}

} // namespace
} // namespace gi::test
