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

// One fixture type for the suite, whichever file its tests are in.
class AtlasGpuTest : public GpuTest {};

} // namespace gi::test
