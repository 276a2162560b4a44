#include "render/FrameRenderer.h"

#include "gl/Shared.h"

namespace gi::render {

bool FrameRenderer::init(const scene::Scene& scene, const Settings& settings,
        gl::ShaderLibrary& shaders, std::string& error) {
    mSettings = settings;
    mScene = std::make_unique<scene::GpuScene>(scene);
    mFrameUniforms = gl::createBuffer(sizeof(shader::FrameUniforms), nullptr,
            GL_DYNAMIC_STORAGE_BIT, "frame/uniforms");
    if (!mShadows.init(shaders, error) || !mForward.init(shaders, error)) return false;
    mLights = scene.lights;
    mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
    return true;
}

void FrameRenderer::setSettings(const Settings& settings) {
    const bool shadowsChanged = !(settings.shadow == mSettings.shadow);
    mSettings = settings;
    if (shadowsChanged) mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
}

void FrameRenderer::setLights(const std::vector<scene::Light>& lights) {
    mLights = lights;
    mScene->setLights(lights);
    mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
}

void FrameRenderer::resizeTargets(glm::ivec2 size) {
    if (size == mRenderSize && mFramebuffer) return;
    mRenderSize = size;
    mColor = gl::createTexture2D(GL_RGBA32F, size, 1, "frame/radiance");
    mDepth = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size, 1, "frame/depth");
    mFramebuffer = gl::createFramebuffer("frame/target");
    glNamedFramebufferTexture(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, mColor.id(), 0);
    glNamedFramebufferTexture(mFramebuffer.id(), GL_DEPTH_ATTACHMENT, mDepth.id(), 0);
}

void FrameRenderer::render(const CameraView& camera, glm::ivec2 outputSize,
        OutputComponent output, gl::GpuProfiler& profiler) {
    resizeTargets(outputSize * mSettings.supersample);

    shader::FrameUniforms frame{};
    frame.viewProjection = camera.viewProjection();
    frame.view = camera.view;
    frame.cameraPosition = glm::vec4(camera.eye, 1.0f);
    frame.shading = glm::vec4(mSettings.specular, mSettings.shininess,
            mSettings.specular > 0.0f ? 1.0f : 0.0f, mSettings.shadow.enabled ? 1.0f : 0.0f);
    const int outputKind = output == OutputComponent::Final    ? OUTPUT_FINAL
                           : output == OutputComponent::Direct ? OUTPUT_DIRECT
                                                               : OUTPUT_INDIRECT;
    frame.counts = glm::ivec4(mScene->lightCount(), outputKind, 0, 0);
    glNamedBufferSubData(mFrameUniforms.id(), 0, sizeof frame, &frame);

    mShadows.execute(*mScene, profiler);
    mForward.execute({*mScene, mShadows, mFrameUniforms}, {mFramebuffer, mRenderSize}, profiler);
}

Image FrameRenderer::readback() const {
    Image full(mRenderSize.x, mRenderSize.y);
    std::vector<float> rgba(std::size_t(mRenderSize.x) * std::size_t(mRenderSize.y) * 4);
    glGetTextureImage(mColor.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
            rgba.data());
    // GL rows run bottom to top; images run top to bottom.
    for (int y = 0; y < mRenderSize.y; ++y) {
        const float* row = rgba.data() + std::size_t(mRenderSize.y - 1 - y) * std::size_t(mRenderSize.x) * 4;
        for (int x = 0; x < mRenderSize.x; ++x) {
            full.set(x, y, {row[x * 4], row[x * 4 + 1], row[x * 4 + 2]});
        }
    }
    return boxDownsample(full, mSettings.supersample);
}

std::vector<gl::MemoryItem> FrameRenderer::memory() const {
    std::vector<gl::MemoryItem> items = mScene->memory();
    for (const gl::MemoryItem& item : mShadows.memory()) items.push_back(item);
    const glm::ivec3 size(mRenderSize, 1);
    items.push_back({"frame/radiance", gl::textureBytes(GL_RGBA32F, size, 1)});
    items.push_back({"frame/depth", gl::textureBytes(GL_DEPTH_COMPONENT32F, size, 1)});
    return items;
}

} // namespace gi::render
