// The camera's G-buffer for the VPL gather: world position and view depth, and the normal of
// the side the eye sees, of the surface in each pixel (shaders/vpl/gbuffer.frag).
// Inputs : GpuScene, FrameUniforms of the camera view.
// Outputs: position() (RGBA32F) and normal() (RGBA16F) at the render size.
#pragma once

#include "gi/vpl/VplImportance.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::vpl {

class VplGBufferPass {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const scene::GpuScene& scene, const gl::Buffer& frameUniforms, glm::ivec2 size,
            gl::GpuProfiler& profiler);
    const gl::Texture& position() const { return mPosition; }
    const gl::Texture& normal() const { return mNormal; }
    glm::ivec2 size() const { return mSize; }
    // The surfaces at the centres of a perSide x perSide grid of cells over the image, read
    // back (waits for the GPU); cells whose centre sees no surface give none.
    [[nodiscard]] std::vector<ViewSample> readSamples(int perSide) const;

private:
    bool resize(glm::ivec2 size);

    gl::ProgramRef mDepthProgram;
    gl::ProgramRef mProgram;
    glm::ivec2 mSize{0};
    gl::Texture mPosition, mNormal, mDepth;
    gl::Framebuffer mFramebuffer;
};

} // namespace gi::vpl
