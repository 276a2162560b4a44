#include "gi/vpl/VplFilterPass.h"

#include "gi/vpl/PixelDispatch.h"
#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::vpl {

bool VplFilterPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"vpl/interleave_filter",
            {{GL_COMPUTE_SHADER, "vpl/interleave_filter.comp"}}, {}}, error);
    return bool(mProgram);
}

void VplFilterPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    const glm::ivec2 size = in.gBuffer.size();
    if (size != mSize) {
        mSize = size;
        // Bilinear: the forward pass reads it at the output's resolution.
        mResult = gl::createTargetTexture({GL_RGBA16F, "vpl/indirect", true}, size);
    }
    gl::GpuScope scope(profiler, "vpl/filter");
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VPL, in.uniforms.id());
    glBindTextureUnit(BIND_TEX_VPL_GATHERED, in.gathered.id());
    glBindTextureUnit(BIND_TEX_VPL_NORMAL, in.gBuffer.normal().id());
    dispatchOverPixels(mResult, size);
}

} // namespace gi::vpl
