// The light injection sums into each voxel must not depend on the order the fragments arrive
// in (voxel_flux_sum.glsl): two renders of one scene must inject the same flux. The test
// makes many fragments contend for each voxel: a sunlit floor in the adaptive plan's 128^3
// voxels, injected through a 2048^2 light view, about 16 light pixels per voxel edge. Summed
// as half floats under the voxel's lock, rounded after each addition, the same voxels' flux
// changed by 1.3-1.9 % between two renders.
#include "GpuTest.h"
#include "TestScenes.h"
#include "VoxelFrame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::test {
namespace {

class InjectionOrderGpuTest : public GpuTest {};

// Each voxel's injected flux per face area: its irradiance times max(area, 1)
// (inject_finalize.comp).
std::vector<double> injectedFlux(const VoxelFrame& frame) {
    const voxel::CascadeVolume& volume = frame.manager().volume();
    std::vector<glm::vec4> irradiance(volume.texelCount());
    glGetTextureImage(frame.manager().textures().irradiance.id(), 0, GL_RGBA, GL_FLOAT,
            GLsizei(irradiance.size() * sizeof(glm::vec4)), irradiance.data());
    std::vector<double> flux;
    for (const glm::vec4& texel : irradiance) {
        flux.push_back(double(texel.r + texel.g + texel.b) * std::max(double(texel.a), 1.0));
    }
    return flux;
}

TEST_F(InjectionOrderGpuTest, TwoRendersInjectTheSameFluxIntoEveryVoxel) {
    scene::Scene scene = floorWithPlate(0.3f, 0.5f);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 3.0f;
    scene.lights = {sun};
    Settings settings;
    settings.voxel.injectResolution = 2048;
    const VoxelFrame first(scene, settings, {32, 32});
    const VoxelFrame second(scene, settings, {32, 32});
    ASSERT_EQ(first.manager().volume().levels(), 1);
    const std::vector<double> a = injectedFlux(first), b = injectedFlux(second);
    ASSERT_EQ(a.size(), b.size());
    double peak = 0.0, largestChange = 0.0;
    int lit = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        peak = std::max(peak, a[i]);
        if (a[i] > 0.0) ++lit;
        largestChange = std::max(largestChange, std::abs(a[i] - b[i]) / std::max(a[i], b[i]));
    }
    std::printf("v = %d, %d lit voxels; largest change of a voxel's flux between renders %.3g of its "
                "flux\n", first.manager().volume().resolution(), lit, largestChange);
    ASSERT_GT(lit, 100) << "the sun lights the floor";
    ASSERT_GT(peak, 0.0);
    // Only the half-float store of the irradiance rounds (2^-11 relative), and a voxel's area
    // from voxelization, which averages a few fragments under its lock.
    EXPECT_LE(largestChange, 2e-3);
}

} // namespace
} // namespace gi::test
