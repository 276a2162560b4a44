// Frame orchestration: owns the GPU scene, the per-view uniforms, the render targets and the
// passes, and runs them in order for one view. The same object serves `voxatlas render`
// (read back to an Image), the viewer (presented to the window) and the tests.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "render/CameraView.h"
#include "render/ForwardPass.h"
#include "scene/GpuScene.h"
#include "render/ShadowPass.h"
#include "render/Image.h"
#include "render/Settings.h"
#include "scene/Scene.h"

#include <memory>
#include <string>

namespace gi::render {

enum class GiMode { Direct, Voxel, Atlas, Reference };
enum class OutputComponent { Final, Direct, Indirect };

class FrameRenderer {
public:
    // Uploads the scene and builds every program; false with one message on failure.
    bool init(const scene::Scene& scene, const Settings& settings, gl::ShaderLibrary& shaders,
            std::string& error);

    void setSettings(const Settings& settings);
    void setLights(const std::vector<scene::Light>& lights);

    // Renders one frame of `camera` at outputSize x render.supersample.
    void render(const CameraView& camera, glm::ivec2 outputSize, OutputComponent output,
            gl::GpuProfiler& profiler);

    // The last frame as linear radiance, box-averaged down to the output size.
    [[nodiscard]] Image readback() const;

    // RGBA32F linear radiance of the last frame (alpha = geometry coverage), render size.
    const gl::Texture& radiance() const { return mColor; }
    glm::ivec2 renderSize() const { return mRenderSize; }
    const scene::GpuScene& gpuScene() const { return *mScene; }

    [[nodiscard]] std::vector<gl::MemoryItem> memory() const;

private:
    void resizeTargets(glm::ivec2 size);

    Settings mSettings;
    std::unique_ptr<scene::GpuScene> mScene;
    std::vector<scene::Light> mLights;
    gl::Buffer mFrameUniforms;
    gl::Texture mColor, mDepth;
    gl::Framebuffer mFramebuffer;
    glm::ivec2 mRenderSize{0};
    ShadowPass mShadows;
    ForwardPass mForward;
};

} // namespace gi::render
