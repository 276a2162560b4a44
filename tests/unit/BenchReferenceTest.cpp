// The bench scores a technique against the path tracer with the materials the GPU renders:
// with material.model=gltf both use glTF's BRDF (BenchRunner::reference), as `voxatlas render
// --mode reference` does; with the default Phong model the path tracer stays Lambertian.
#include "TestScenes.h"

#include "bench/BenchRunner.h"
#include "reference/ReferenceRenderer.h"
#include "scene/CameraView.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace gi::test {
namespace {

constexpr int kSize = 24;

double meanAbsoluteDifference(const core::Image& a, const core::Image& b) {
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const glm::vec3 d = a.at(x, y) - b.at(x, y);
            sum += double(std::abs(d.r) + std::abs(d.g) + std::abs(d.b));
        }
    }
    return sum / double(a.width * a.height);
}

struct Renders {
    core::Image bench, glossy, lambert;
};

Renders renders(const Settings& settings) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_glossy.gltf");
    bench::BenchScene benchScene;
    benchScene.name = "cornell_glossy";
    benchScene.scene = &scene;
    benchScene.camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    benchScene.size = glm::ivec2(kSize);
    std::string error;
    Renders result;
    result.bench = bench::BenchRunner(settings, {}).reference(benchScene, error).indirect;
    EXPECT_FALSE(result.bench.empty()) << error;
    ReferenceSettings direct = settings.reference;
    direct.glossy = true;
    result.glossy = reference::renderReference(scene, benchScene.camera, kSize, kSize, direct).indirect;
    direct.glossy = false;
    result.lambert = reference::renderReference(scene, benchScene.camera, kSize, kSize, direct).indirect;
    return result;
}

Settings smallReference() {
    Settings settings;
    settings.reference.spp = 16;
    return settings;
}

TEST(BenchReference, GltfMaterialsAreScoredAgainstTheGlossyPathTracer) {
    Settings settings = smallReference();
    settings.materialModel = MATERIAL_GLTF;
    const Renders r = renders(settings);
    // The metal block and the Fresnel factor change the light: the two models differ.
    ASSERT_GT(meanAbsoluteDifference(r.glossy, r.lambert), 1e-3);
    EXPECT_EQ(meanAbsoluteDifference(r.bench, r.glossy), 0.0);
}

TEST(BenchReference, PhongMaterialsAreScoredAgainstTheLambertianPathTracer) {
    const Renders r = renders(smallReference());
    ASSERT_GT(meanAbsoluteDifference(r.glossy, r.lambert), 1e-3);
    EXPECT_EQ(meanAbsoluteDifference(r.bench, r.lambert), 0.0);
}

} // namespace
} // namespace gi::test
