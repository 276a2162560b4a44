// fluxSumScale: the fixed-point units light injection sums flux in (voxel_flux_sum.glsl).
// No voxel's sum may reach 2^31 units even if every pixel of every view sent its light's
// strongest flux into one voxel, and the resolution follows the lights' flux, not their units.
#include "gi/voxel/InjectPass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace gi::test {
namespace {

scene::Light pointLight(float intensity) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.intensity = intensity;
    light.position = {0.0f, 1.0f, 0.0f};
    return light;
}

scene::Light sun(float irradiance) {
    scene::Light light;
    light.type = scene::LightType::Directional;
    light.intensity = irradiance;
    light.direction = {0.0f, -1.0f, 0.0f};
    return light;
}

const scene::Aabb kRoom{{-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}};

// The most flux / face area that every view's pixels could bring one finest voxel, in units.
double worstSumInUnits(const std::vector<scene::Light>& lights,
        const std::vector<voxel::LightView>& views, int resolution, float voxel, float exposure) {
    const double scale = voxel::fluxSumScale(lights, views, resolution, voxel, exposure);
    double flux = 0.0;
    for (const voxel::LightView& view : views) {
        flux += scene::lightStrength(lights[std::size_t(view.light)]) * exposure * view.footprint *
                double(resolution) * resolution;
    }
    return flux / (double(voxel) * voxel) * scale;
}

TEST(FluxSumScale, NoVoxelCanReachTwoToThe31EvenWithEightTimesTheLightsFlux) {
    const std::vector<scene::Light> lights = {pointLight(0.3f), sun(4.0f)};
    for (int resolution : {64, 466, 1024}) {
        for (float voxel : {0.002f, 0.02f, 0.3f}) {
            for (float exposure : {0.0625f, 1.0f, 64.0f}) {
                const auto views = scene::lightViews(lights, kRoom, resolution);
                ASSERT_EQ(views.size(), 7u);   // six cube faces and the sun's view
                const double worst = worstSumInUnits(lights, views, resolution, voxel, exposure);
                const std::string where = std::to_string(resolution) + " pixels, voxel " +
                        std::to_string(voxel) + " m, exposure " + std::to_string(exposure);
                EXPECT_LE(8.0 * worst, 2147483648.0) << where;
                // ... and as fine as that allows: twice the scale would pass it.
                EXPECT_GT(16.0 * worst, 2147483648.0) << where;
            }
        }
    }
}

TEST(FluxSumScale, IsAPowerOfTwoThatFollowsTheLightsUnits) {
    const auto views = scene::lightViews({pointLight(0.3f)}, kRoom, 256);
    const double scale = voxel::fluxSumScale({pointLight(0.3f)}, views, 256, 0.01f, 1.0f);
    EXPECT_EQ(std::exp2(std::round(std::log2(scale))), scale);
    // A light 1024 times stronger (or pre-exposed 1024 times higher) gets 1024 times coarser
    // units: its sums keep the same relative resolution.
    EXPECT_EQ(voxel::fluxSumScale({pointLight(0.3f * 1024.0f)}, views, 256, 0.01f, 1.0f),
            scale / 1024.0);
    EXPECT_EQ(voxel::fluxSumScale({pointLight(0.3f)}, views, 256, 0.01f, 1024.0f), scale / 1024.0);
    // Voxels eight times larger: a point light's footprint is a solid angle, so the flux per
    // face area falls, and the units grow, with the voxel's face.
    const double larger = voxel::fluxSumScale({pointLight(0.3f)}, views, 256, 0.08f, 1.0f);
    EXPECT_EQ(larger, scale * 64.0);
}

TEST(FluxSumScale, IsOneWithoutFluxToSum) {
    EXPECT_EQ(voxel::fluxSumScale({}, {}, 256, 0.01f, 1.0f), 1.0);
    const auto views = scene::lightViews({pointLight(0.0f)}, kRoom, 256);
    EXPECT_EQ(voxel::fluxSumScale({pointLight(0.0f)}, views, 256, 0.01f, 1.0f), 1.0);
}

} // namespace
} // namespace gi::test
