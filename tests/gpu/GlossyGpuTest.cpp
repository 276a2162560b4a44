// Voxel GI with glossy materials (material.model=gltf) on the scene suite's glossy Cornell
// box: the specular cone lights the metal block about as the path tracer with the same BRDF
// does (at the defaults, with the quality preset, and with anisotropic voxels), the glossy model
// changes the indirect light as much as it changes the path tracer's, and
// material.specular=0 leaves every model Lambertian.
#include "GpuTest.h"
#include "TestScenes.h"

#include "bench/BenchSweep.h"
#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"
#include "scene/CameraView.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gi::test {
namespace {

constexpr int kSize = 96;

scene::Scene glossyBox() { return loadTestScene("assets/scene_suite/cornell_glossy.gltf"); }

scene::CameraView camera(const scene::Scene& scene) {
    return scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
}

core::Image voxelIndirect(const scene::Scene& scene, const Settings& settings) {
    RenderRequest request;
    request.width = request.height = kSize;
    request.output = render::OutputComponent::Indirect;
    request.settings = settings;
    request.mode = render::GiMode::Voxel;
    return renderScene(scene, request);
}

// Pixels wholly covered by the metal block: the path tracer's view of the scene with the
// metal glowing (radiance 100) and no light, where nothing else comes near 90.
std::vector<bool> metalPixels(scene::Scene scene) {
    for (scene::Material& m : scene.materials) {
        if (m.metallicFactor > 0.0f) m.emissiveFactor = glm::vec3(100.0f);
    }
    scene.lights.clear();
    ReferenceSettings settings;
    settings.spp = 4;
    const reference::ReferenceResult glow =
            reference::renderReference(scene, camera(scene), kSize, kSize, settings);
    std::vector<bool> mask(std::size_t(kSize * kSize), false);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            mask[std::size_t(y * kSize + x)] = glow.direct.at(x, y).r > 90.0f;
        }
    }
    return mask;
}

class GlossyGpuTest : public GpuTest {};

// The metal block's indirect light, voxel GI with `settings` over the path tracer's with the
// same BRDF (256 spp), summed over the pixels the block wholly covers.
double metalBlockShare(const Settings& settings) {
    const scene::Scene scene = glossyBox();
    const std::vector<bool> metal = metalPixels(scene);
    int pixels = 0;
    for (bool m : metal) pixels += m ? 1 : 0;
    EXPECT_GT(pixels, 50);
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 256;
    referenceSettings.glossy = true;
    const reference::ReferenceResult truth = reference::renderReference(scene, camera(scene),
            kSize, kSize, referenceSettings);
    const double voxel = sumOverMask(voxelIndirect(scene, settings), metal);
    const double reference = sumOverMask(truth.indirect, metal);
    std::printf("metal block indirect light over %d pixels: voxel %.3f, reference %.3f, "
                "ratio %.3f\n", pixels, voxel, reference, voxel / reference);
    EXPECT_GT(reference, 0.0);
    return reference > 0.0 ? voxel / reference : 0.0;
}

// A metal has no diffuse term: its indirect light is the specular cone's (and the share of
// the lobe taken from the diffuse cones). With the default plan it holds 0.95 of the path
// tracer's here (1.00 over scripts/measure_glossy.py's inner pixels); 1.46 (1.54) when the
// cone took half the lobe and the hemisphere's mean the other half: the block's faces look
// out of the open box and their lobes' tails see the opening. At 48x48 the trace (24x24
// after voxel.trace_scale) holds too few of the block's pixels to say (0.54 and 1.27).
// Without the cone the block's indirect light is 0.
TEST_F(GlossyGpuTest, SpecularConeLightsTheMetalBlockRoughlyAsThePathTracer) {
    Settings settings;
    settings.materialModel = MATERIAL_GLTF;
    const double share = metalBlockShare(settings);
    EXPECT_GT(share, 0.8);
    EXPECT_LT(share, 1.2);
}

Settings qualityPresetSettings() {
    Settings settings;
    settings.materialModel = MATERIAL_GLTF;
    std::string error;
    for (const bench::SettingChange& change : bench::voxelQualityPreset()) {
        EXPECT_TRUE(applySetting(settings, change.key + "=" + change.value, error)) << error;
    }
    return settings;
}

// The quality preset (37 cones, v = 64, one level of up to 256^3): its specular cone reads the
// light pyramid's six faces by the area each shows the cone's directions.
TEST_F(GlossyGpuTest, QualityPresetLightsTheMetalBlockRoughlyAsThePathTracer) {
    const double share = metalBlockShare(qualityPresetSettings());
    EXPECT_GT(share, 0.8);
    EXPECT_LT(share, 1.2);
}

// Anisotropic voxels under the quality preset: the specular cone reads the faces all the
// cone's directions see (voxel_directional.glsl's faceWeightsOverCone), 0.85 of the path
// tracer's (when the preset took them); read by the axis' squared components, what the axis
// meets head-on, the block got about 0.66 at the defaults (accuracy-analysis.md).
TEST_F(GlossyGpuTest, AnisotropicVoxelsLightTheMetalBlockRoughlyAsThePathTracer) {
    Settings settings = qualityPresetSettings();
    settings.voxel.anisotropic = true;
    const double share = metalBlockShare(settings);
    EXPECT_GT(share, 0.8);
    EXPECT_LT(share, 1.2);
}

double sumOf(const core::Image& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += double(v);
    return sum;
}

// The indirect light's specular component, the glossy image less the Lambertian one, nets
// the light the lobes add against what the metal's missing diffuse term and every
// dielectric's Fresnel factor take away: -5% of the box's indirect light in the path tracer.
// Its sum over the image is within 15% of the path tracer's only when the light the voxels
// send on is what the glossy surfaces reflect (voxel_reflectance.glsl): with the base colour
// in its place the sum is 0.76 of the path tracer's (scripts/measure_glossy.py).
TEST_F(GlossyGpuTest, GlossyModelChangesTheIndirectLightAsInThePathTracer) {
    const scene::Scene scene = glossyBox();
    Settings glossy;
    glossy.materialModel = MATERIAL_GLTF;
    Settings lambert = glossy;
    lambert.specular = 0.0f;
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 512;
    const reference::ReferenceResult lambertTruth = reference::renderReference(scene,
            camera(scene), kSize, kSize, referenceSettings);
    referenceSettings.glossy = true;
    const reference::ReferenceResult glossyTruth = reference::renderReference(scene,
            camera(scene), kSize, kSize, referenceSettings);
    const double reference = sumOf(glossyTruth.indirect) - sumOf(lambertTruth.indirect);
    const double voxel = sumOf(voxelIndirect(scene, glossy)) - sumOf(voxelIndirect(scene, lambert));
    std::printf("specular component of the indirect light: voxel %.1f, reference %.1f (of "
                "%.1f), ratio %.3f\n", voxel, reference, sumOf(lambertTruth.indirect),
            voxel / reference);
    ASSERT_LT(reference, 0.0);
    EXPECT_GT(voxel / reference, 0.85);
    EXPECT_LT(voxel / reference, 1.15);
}

TEST_F(GlossyGpuTest, NoSpecularIsLambertianInEveryModel) {
    const scene::Scene scene = glossyBox();
    Settings phong;
    phong.specular = 0.0f;
    Settings gltf = phong;
    gltf.materialModel = MATERIAL_GLTF;
    const core::Image a = voxelIndirect(scene, phong);
    const core::Image b = voxelIndirect(scene, gltf);
    gltf.specular = 1.0f;
    const core::Image glossy = voxelIndirect(scene, gltf);
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    ASSERT_EQ(a.rgb.size(), glossy.rgb.size());
    // Voxelization averages fragments in whatever order the GPU delivers them, so two
    // frames of one setting differ a little, and a voxel whose plane moves by a rounding
    // error can move one pixel by a few percent of the peak (llvmpipe over OSMesa: 1.7%
    // between the two models without specular): compare the mean absolute difference over
    // the mean level, against what the glossy model itself changes.
    double level = 0.0, same = 0.0, changed = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        level += a.rgb[i];
        same += std::abs(a.rgb[i] - b.rgb[i]);
        changed += std::abs(a.rgb[i] - glossy.rgb[i]);
    }
    same /= level;
    changed /= level;
    std::printf("mean difference over the mean level: phong vs gltf without specular %.3g, "
                "vs gltf %.3g\n", same, changed);
    EXPECT_LE(same, 2e-3);
    EXPECT_GT(changed, 0.05);
}

} // namespace
} // namespace gi::test
