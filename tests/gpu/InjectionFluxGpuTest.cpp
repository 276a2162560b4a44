// The light injected into the voxels, against the flux a point light sends: in the suite's
// Cornell box the light hangs 1 cm under the ceiling, so the ceiling takes nearly half of its
// power, most of it within a few centimetres at grazing incidence over voxels of 0.5-2 cm.
// The voxels' irradiance times their face area, summed over the ceiling's voxels, must be the
// flux through the ceiling's rectangle as seen from the light, at every voxel size, and the
// part within 5 cm of the point over the light the flux through that disc.
#include "GpuTest.h"
#include "TestScenes.h"
#include "VoxelFrame.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace gi::test {
namespace {

// Solid angle of the rectangle [0, a] x [0, b] at height h over its corner.
double cornerRectangleSolidAngle(double a, double b, double h) {
    return std::atan(a * b / (h * std::sqrt(h * h + a * a + b * b)));
}

class InjectionFluxGpuTest : public GpuTest {};

TEST_F(InjectionFluxGpuTest, CeilingTakesThePointLightsFluxAtEveryVoxelSize) {
    // assets/scene_suite/cornell_classic.gltf: the ceiling at y = 0.5488 over x in [0, 0.556]
    // and z in [-0.559, 0], the light (0.3 W/sr) at (0.278, 0.5388, -0.2795).
    const glm::vec3 light(0.278f, 0.5388f, -0.2795f);
    const double intensity = 0.3, h = 0.5488 - 0.5388;
    double omega = 0.0;
    for (double a : {0.278, 0.556 - 0.278})
        for (double b : {0.2795, 0.559 - 0.2795}) omega += cornerRectangleSolidAngle(a, b, h);
    const double ceilingFlux = intensity * omega;
    constexpr double kDisc = 0.05;
    const double discFlux = intensity * 2.0 * glm::pi<double>() * (1.0 - h / std::sqrt(h * h + kDisc * kDisc));
    for (int resolution : {32, 64, 128}) {
        const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_classic.gltf");
        Settings settings;
        settings.specular = 0.0f;
        settings.voxel.resolution = resolution;   // the adaptive plan: one level of v^3
        VoxelFrame frame(scene, settings, {32, 32});
        const voxel::CascadeVolume& volume = frame.manager().volume();
        ASSERT_EQ(volume.levels(), 1);
        const int v = volume.resolution();
        std::vector<glm::vec4> irradiance(volume.texelCount()), normal(volume.texelCount()),
                albedo(volume.texelCount());
        for (auto [texture, texels] : {std::pair{&frame.manager().textures().irradiance, &irradiance},
                     std::pair{&frame.manager().textures().normal, &normal},
                     std::pair{&frame.manager().textures().albedo, &albedo}}) {
            glGetTextureImage(texture->id(), 0, GL_RGBA, GL_FLOAT,
                    GLsizei(texels->size() * sizeof(glm::vec4)), texels->data());
        }
        const float size = volume.voxelSize(0);
        double ceiling = 0.0, disc = 0.0;
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    const std::size_t t = (std::size_t(z) * v + std::size_t(y)) * v + std::size_t(x);
                    const glm::vec3 centre = volume.origin(0) + (glm::vec3(x, y, z) + 0.5f) * size;
                    // The ceiling's voxels: occupied, facing down, in the box's top half.
                    if (albedo[t].a <= 0.0f || normal[t].y > -0.5f || centre.y < 0.5f) continue;
                    // Irradiance x coverage is the voxel's flux over its face area.
                    const double flux = double(irradiance[t].g) * size * size / frame.exposure();
                    ceiling += flux;
                    if (glm::length(glm::vec2(centre.x - light.x, centre.z - light.z)) < kDisc) disc += flux;
                }
        std::printf("v = %d: ceiling %.4f W (analytic %.4f), within %.0f cm %.4f W (analytic %.4f)\n",
                v, ceiling, ceilingFlux, kDisc * 100.0, disc, discFlux);
        EXPECT_NEAR(ceiling / ceilingFlux, 1.0, 0.03) << "v = " << v;
        EXPECT_NEAR(disc / discFlux, 1.0, 0.03) << "v = " << v;
    }
}

} // namespace
} // namespace gi::test
