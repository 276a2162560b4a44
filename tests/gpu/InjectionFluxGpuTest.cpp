// The light injected into the voxels, against the flux a point light sends: in the suite's
// Cornell box the light hangs 1 cm under the ceiling, so the ceiling takes nearly half of its
// power, most of it within a few centimetres at grazing incidence over voxels of 0.5-2 cm.
// The voxels' irradiance times their face area, summed over the ceiling's voxels, must be the
// flux through the ceiling's rectangle as seen from the light, at every voxel size, and the
// part within 5 cm of the point over the light the flux through that disc.
// Thin strips under a sun: the flux the light views put into voxels must stay in voxels the
// voxelization raster found a surface in (inject_finalize.comp drops the rest).
#include "GpuTest.h"
#include "TestScenes.h"
#include "VoxelFrame.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace gi::test {
namespace {

// Solid angle of the rectangle [0, a] x [0, b] at height h over its corner.
double cornerRectangleSolidAngle(double a, double b, double h) {
    return std::atan(a * b / (h * std::sqrt(h * h + a * a + b * b)));
}

class InjectionFluxGpuTest : public GpuTest {};

// A strip along x at height y, `width` wide around z, facing +Y, material 0.
scene::Primitive horizontalStrip(float halfLength, float width, float y, float z) {
    scene::Primitive p = horizontalSquare(1.0f, y);
    p.localBounds = {};
    for (glm::vec3& v : p.positions) {
        v = glm::vec3(v.x * halfLength, y, z + 0.5f * width * v.z);
        p.localBounds.extend(v);
    }
    return p;
}

// The flux the voxels hold (W, the exposure removed): each voxel's irradiance times
// max(area, 1) face areas (inject_finalize.comp).
double voxelFlux(const VoxelFrame& frame) {
    const voxel::CascadeVolume& volume = frame.manager().volume();
    std::vector<glm::vec4> irradiance(volume.texelCount());
    glGetTextureImage(frame.manager().textures().irradiance.id(), 0, GL_RGBA, GL_FLOAT,
            GLsizei(irradiance.size() * sizeof(glm::vec4)), irradiance.data());
    const double faceArea = double(volume.voxelSize(0)) * double(volume.voxelSize(0));
    double flux = 0.0;
    for (const glm::vec4& texel : irradiance) {
        flux += double(texel.g) * std::max(double(texel.a), 1.0) * faceArea;
    }
    return flux / frame.exposure();
}

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

// Forty strips 3 mm wide at 2.3 cm spacing (so they sit at every offset across the voxels),
// lit straight down by a sun, in the adaptive plan's one level of 128^3 voxels (8.6 mm: a
// strip is 0.35 voxels wide), voxelized through its raster of 2 pixels per voxel edge. The
// light views see every strip (the plan's have 4 pixels per voxel edge; these, 0.3 mm
// pixels, inject each strip's flux exactly). With one sample a pixel (voxel.msaa=1) the
// raster's samples lie half a voxel apart and miss a strip's voxels whenever it runs between
// them: the voxels hold 0.66 of the flux. With the plan's four samples a pixel, all of it
// (0.997).
TEST_F(InjectionFluxGpuTest, ThinStripsKeepTheSunsFlux) {
    scene::Scene scene;
    scene::Material grey;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    scene.materials = {grey};
    constexpr int kStrips = 40;
    constexpr float kHalfLength = 0.5f, kWidth = 0.003f, kSpacing = 0.023f;
    for (int i = 0; i < kStrips; ++i) {
        addPrimitive(scene, horizontalStrip(kHalfLength, kWidth, i % 2 == 0 ? 0.0f : 0.05f,
                                    (float(i) - 0.5f * float(kStrips - 1)) * kSpacing));
    }
    scene.cameras.push_back(lookAtCamera({0.0f, 1.0f, 1.5f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    sun.intensity = 3.0f;
    scene.lights = {sun};
    Settings settings;
    settings.specular = 0.0f;
    settings.voxel.size = 0.01f;
    // Light views of 0.3 mm pixels, ten across a strip: the flux they inject is the sun's
    // within a fraction of a percent, whichever pixels a strip's edges fall on.
    settings.voxel.injectResolution = 4096;
    const double expected = double(sun.intensity) * kStrips * 2.0 * kHalfLength * kWidth;
    // One sample a pixel first, printed to show what the samples recover; then the plan's.
    for (const int samples : {1, 0}) {
        settings.voxel.msaa = samples;
        const VoxelFrame frame(scene, settings, {32, 32});
        const voxel::CascadeVolume& volume = frame.manager().volume();
        ASSERT_EQ(volume.levels(), 1);
        ASSERT_EQ(volume.resolution(), 128);
        ASSERT_EQ(frame.renderer().plan().voxel.multiplier, 2);
        const int used = frame.renderer().plan().voxel.msaa;
        const double held = voxelFlux(frame);
        std::printf("strips %.3f of a voxel wide, %d sample%s a raster pixel: the voxels hold "
                    "%.4f W of the %.4f W the sun sends them (%.3f)\n",
                kWidth / volume.voxelSize(0), used, used == 1 ? "" : "s", held, expected,
                held / expected);
        if (samples != 0) continue;
        EXPECT_EQ(used, 4);
        EXPECT_GT(held / expected, 0.95);
        EXPECT_LT(held / expected, 1.02);
    }
}

} // namespace
} // namespace gi::test
