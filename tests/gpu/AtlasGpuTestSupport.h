// Shared by the atlas GPU tests (Atlas*GpuTest.cpp): settings small enough for llvmpipe,
// atlas-GI frames of one scene kept alive for read-backs, and atlas texel coordinates.
#pragma once

#include "GpuTest.h"
#include "TestScenes.h"

#include "gi/atlas/AtlasGi.h"

#include <glad/gl.h>

#include <optional>
#include <string>
#include <vector>

namespace gi::test {

// Small atlases and sample counts keep each test to seconds on llvmpipe; the disk cache is
// off so tests never touch the user's cache directory.
inline Settings atlasSettings(int resolution = 256, int samples = 64) {
    Settings settings = thesisAllocation();
    settings.atlas.resolution = resolution;
    settings.atlas.samples = samples;
    settings.atlas.cache = false;
    return settings;
}

inline std::vector<glm::vec4> readAtlas(const gl::Texture& texture, int resolution) {
    std::vector<glm::vec4> texels(std::size_t(resolution) * std::size_t(resolution));
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT,
            GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
    return texels;
}

// Atlas-GI frames of one scene; the renderer stays alive for read-backs.
class AtlasFrame {
public:
    AtlasFrame(const scene::Scene& scene, const Settings& settings) : mScene(scene) {
        std::string error;
        EXPECT_TRUE(mRenderer.init(mScene, settings, mShaders, error)) << error;
        EXPECT_TRUE(mRenderer.setMode(render::GiMode::Atlas, error)) << error;
    }
    void render(glm::ivec2 size, render::OutputComponent output = render::OutputComponent::Final,
            int frames = 1, std::optional<scene::Camera> camera = std::nullopt) {
        const scene::CameraView view = scene::cameraFromScene(
                camera ? *camera : mScene.cameras[0], float(size.x) / float(size.y), mScene.bounds);
        gl::GpuProfiler profiler;
        for (int i = 0; i < frames; ++i) mRenderer.render(view, size, output, profiler);
        profiler.flush();
    }
    const atlas::AtlasGi& gi() const {
        return static_cast<const atlas::AtlasGi&>(*mRenderer.technique());
    }
    // The lit layer in W/(m^2 sr): the atlas holds it times the scene's pre-exposure
    // (scene/Exposure.h).
    std::vector<glm::vec4> lit() const {
        std::vector<glm::vec4> texels = readAtlas(gi().textures().lit, gi().textures().resolution);
        const float exposure = mRenderer.gpuScene().exposure();
        for (glm::vec4& t : texels) t = glm::vec4(glm::vec3(t) / exposure, t.a);
        return texels;
    }
    core::Image image() const { return mRenderer.readback(); }
    render::FrameRenderer& renderer() { return mRenderer; }

private:
    scene::Scene mScene;
    gl::ShaderLibrary mShaders;
    render::FrameRenderer mRenderer;
};

inline glm::dvec2 texelPosition(const atlas::Atlas& atlas, std::size_t triangle, int corner) {
    return glm::dvec2(atlas.vertices[atlas.indices[3 * triangle + std::size_t(corner)]].uv) *
            double(atlas.resolution);
}

// The atlas texel of world point p on triangle t (barycentric in world space).
inline glm::ivec2 texelOf(
        const atlas::AtlasMesh& mesh, const atlas::Atlas& atlas, std::size_t t, glm::dvec3 p) {
    const auto corner = [&](int k) {
        return glm::dvec3(
                mesh.positions[atlas.vertices[atlas.indices[3 * t + std::size_t(k)]].source]);
    };
    const glm::dvec3 a = corner(0), e1 = corner(1) - a, e2 = corner(2) - a, r = p - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double r1 = glm::dot(r, e1), r2 = glm::dot(r, e2), det = d11 * d22 - d12 * d12;
    const double w1 = (d22 * r1 - d12 * r2) / det, w2 = (d11 * r2 - d12 * r1) / det;
    const glm::dvec2 uv = (1.0 - w1 - w2) * texelPosition(atlas, t, 0) +
            w1 * texelPosition(atlas, t, 1) + w2 * texelPosition(atlas, t, 2);
    return glm::ivec2(glm::floor(uv));
}

// E at the centre of a square's floor twin 0.5 m under it, per unit radiance of the square:
// 4 / sqrt(2) * atan(1 / sqrt(2)) (the point-to-rectangle form factor times pi).
constexpr double kEmitterFormFactor = 1.7408437;

// Mean E_ind over the 3x3 texels around the centre of a floor whose first triangle holds the
// origin (E is flat there: 0.2% over 1 cm).
inline glm::dvec3 floorCentreIrradiance(const atlas::Atlas& atlas, const atlas::AtlasMesh& mesh,
        const std::vector<glm::vec4>& lit) {
    const int r = atlas.resolution;
    const glm::ivec2 centre = texelOf(mesh, atlas, 0, glm::dvec3(0.0));
    glm::dvec3 sum(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            sum += glm::dvec3(
                    lit[std::size_t(centre.y + dy) * std::size_t(r) + std::size_t(centre.x + dx)]);
        }
    return sum / 9.0;
}

// One fixture type for the suite, whichever file its tests are in.
class AtlasGpuTest : public GpuTest {};

} // namespace gi::test
