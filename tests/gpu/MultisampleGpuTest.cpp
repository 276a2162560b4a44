// render.msaa: the final shading pass takes several samples a pixel, shades each surface a
// pixel's samples cover once and averages them, so a pixel where surfaces meet holds each by
// the area it covers, as the path tracer's pixel does (docs/conventions.md); supersampling
// (render.supersample) averages the pixel's square by brute force and is the yardstick.
#include "GpuTest.h"
#include "TestScenes.h"

#include <cmath>
#include <cstdio>

namespace gi::test {
namespace {

class MultisampleGpuTest : public GpuTest {};

// Mean absolute difference of two images of one size, over every channel.
double meanDifference(const core::Image& a, const core::Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(double(a.rgb[i] - b.rgb[i]));
    return sum / double(a.rgb.size());
}

// The Cornell box with every surface glowing at its own colour and no light, at 64x64: each
// surface is flat, so the image differs between the pixel's centre and its square only at
// the silhouettes (the blocks against the walls, the box against the empty background). Four
// samples a pixel must take the image at least a third of the way from one sample towards
// 4x4 supersampling, and change no pixel that one surface covers whole.
TEST_F(MultisampleGpuTest, FourSamplesAPixelApproachTheSupersampledSilhouettes) {
    scene::Scene scene = loadTestScene("assets/scene_suite/cornell_classic.gltf");
    for (scene::Material& material : scene.materials) {
        material.emissiveFactor = glm::vec3(material.baseColorFactor);
    }
    scene.lights.clear();
    RenderRequest request;
    request.settings.supersample = 4;
    const core::Image square = renderScene(scene, request);
    request.settings.supersample = 1;
    request.settings.msaa = 1;
    const core::Image centre = renderScene(scene, request);
    request.settings.msaa = 4;
    const core::Image samples = renderScene(scene, request);
    ASSERT_FALSE(square.empty());
    ASSERT_FALSE(centre.empty());
    ASSERT_FALSE(samples.empty());

    const double centreError = meanDifference(centre, square);
    const double samplesError = meanDifference(samples, square);
    std::printf("mean difference from 4x4 supersampling: 1 sample %.5f, 4 samples %.5f\n",
            centreError, samplesError);
    EXPECT_LT(samplesError, centreError * 2.0 / 3.0);

    int changed = 0, interior = 0;
    for (int y = 1; y + 1 < centre.height; ++y) {
        for (int x = 1; x + 1 < centre.width; ++x) {
            // A pixel whose neighbours all match it lies inside one surface's smooth light.
            bool smooth = true;
            for (int dy = -1; dy <= 1 && smooth; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::vec3 d = centre.at(x + dx, y + dy) - centre.at(x, y);
                    if (std::abs(d.r) + std::abs(d.g) + std::abs(d.b) >
                            0.05f * (centre.at(x, y).r + centre.at(x, y).g + 1e-3f)) {
                        smooth = false;
                        break;
                    }
                }
            }
            if (!smooth) continue;
            ++interior;
            const glm::vec3 d = samples.at(x, y) - centre.at(x, y);
            const glm::vec3 c = centre.at(x, y);
            if (std::abs(d.r) + std::abs(d.g) + std::abs(d.b) > 1e-4f * (c.r + c.g + c.b + 1e-3f)) {
                ++changed;
            }
        }
    }
    std::printf("%d of %d pixels inside one surface changed\n", changed, interior);
    EXPECT_GT(interior, 1000);
    EXPECT_EQ(changed, 0);
}

// More samples than the GL offers for the radiance target's format take the most it offers
// (llvmpipe: 4 for RGBA32F) instead of leaving the frame without a framebuffer.
TEST_F(MultisampleGpuTest, MoreSamplesThanTheGlOffersTakeItsMost) {
    RenderRequest request;
    request.scenePath = "assets/scene_suite/cornell_classic.gltf";
    request.settings.specular = 0.0f;
    request.settings.msaa = 8;
    const core::Image image = renderScene(request);
    ASSERT_FALSE(image.empty());
    double sum = 0.0;
    for (float v : image.rgb) sum += double(v);
    EXPECT_GT(sum, 0.0);
}

} // namespace
} // namespace gi::test
