// Base-colour and emissive textures in the final image. The forward pass is compiled for the
// kinds of texture the scene's materials have (FrameSwitches::materialTextures), so both
// lookups must still run where the scene has both kinds. A floor under a sun straight down
// carries a base-colour texture white on its left half and black on its right, and an
// emissive texture the other way round: the left half shows rho/pi x E and no emission, the
// right half its emission and no reflected light.
#include "GpuTest.h"
#include "TestScenes.h"

#include "scene/CameraView.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

constexpr int kClampToEdge = 33071;   // GL_CLAMP_TO_EDGE, as a glTF sampler names it

// 8 x 1 texels, the left four `left`, the right four `right` (grey levels, sRGB-encoded).
scene::Texture halves(std::uint8_t left, std::uint8_t right) {
    scene::Texture t;
    t.width = 8;
    t.height = 1;
    for (int x = 0; x < t.width; ++x) {
        const std::uint8_t v = x < 4 ? left : right;
        t.rgba8.insert(t.rgba8.end(), {v, v, v, 255});
    }
    t.wrapS = t.wrapT = kClampToEdge;
    return t;
}

class MaterialTextureGpuTest : public GpuTest {};

TEST_F(MaterialTextureGpuTest, BaseColourAndEmissiveTexturesBothReachTheImage) {
    scene::Scene s;
    s.textures = {halves(255, 0), halves(0, 255)};
    scene::Material m;
    m.baseColorTexture = 0;
    m.emissiveTexture = 1;
    constexpr float kEmission = 0.3f;
    m.emissiveFactor = glm::vec3(kEmission);
    s.materials.push_back(m);
    scene::Primitive floor = horizontalSquare(1.0f, 0.0f);
    for (const glm::vec3& p : floor.positions) {
        floor.texcoords0.push_back({0.5f * (p.x + 1.0f), 0.5f * (p.z + 1.0f)});
    }
    addPrimitive(s, floor);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.intensity = 2.0f;
    s.lights.push_back(sun);
    s.cameras.push_back(lookAtCamera({0.0f, 2.0f, 0.001f}, {0.0f, 0.0f, 0.0f}, 50.0f));

    constexpr int kSize = 64;
    RenderRequest request;
    request.width = request.height = kSize;
    request.settings.specular = 0.0f;
    const core::Image image = renderScene(s, request);
    ASSERT_FALSE(image.empty());
    const scene::CameraView camera = scene::cameraFromScene(s.cameras[0], 1.0f, s.bounds);
    const float reflected = 1.0f / glm::pi<float>() * sun.intensity;
    int left = 0, right = 0;
    for (int y = 2; y < kSize; y += 4) {
        for (int x = 2; x < kSize; x += 4) {
            glm::vec3 p;
            if (!pixelOnPlaneY(camera, kSize, kSize, x, y, 0.0f, p)) continue;
            if (std::abs(p.x) > 0.95f || std::abs(p.z) > 0.95f) continue;
            const float u = 0.5f * (p.x + 1.0f);
            const float observed = image.at(x, y).r;
            // Texel centres lie 1/16 apart: away from the middle one texel's filter reads
            // one half only.
            if (u < 0.43f) {
                EXPECT_NEAR(observed, reflected, 0.01f * reflected)
                        << "left half at (" << p.x << ", " << p.z << "): white, not emitting";
                ++left;
            } else if (u > 0.57f) {
                EXPECT_NEAR(observed, kEmission, 0.01f * kEmission)
                        << "right half at (" << p.x << ", " << p.z << "): black, emitting";
                ++right;
            }
        }
    }
    EXPECT_GT(left, 40);
    EXPECT_GT(right, 40);
}

} // namespace
} // namespace gi::test
