#include "gi/vpl/VplDebugPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <algorithm>

namespace gi::vpl {

bool VplDebugPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mSplat = shaders.build({"vpl/debug_splat", {{GL_COMPUTE_SHADER, "vpl/debug_splat.comp"}}, {}},
            error);
    if (!mSplat) return false;
    mCompose = shaders.build({"vpl/debug_compose",
            {{GL_COMPUTE_SHADER, "vpl/debug_compose.comp"}}, {}}, error);
    return bool(mCompose);
}

void VplDebugPass::execute(int view, const Inputs& in, gl::GpuProfiler& profiler) {
    const glm::ivec2 size = in.gBuffer.size();
    if (size.x <= 0 || size.y <= 0) return;
    if (size != mSize) {
        mSize = size;
        mIds = gl::createTargetTexture({GL_R32UI, "vpl/debug_view_ids"}, size);
        mImage = gl::createTargetTexture({GL_RGBA32F, "vpl/debug_view"}, size);
    }
    gl::GpuScope scope(profiler, "vpl/debug_view");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VPL, in.uniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_VPLS, in.vpls.id());
    glBindTextureUnit(BIND_TEX_VPL_POSITION, in.gBuffer.position().id());
    glBindTextureUnit(BIND_TEX_VPL_NORMAL, in.gBuffer.normal().id());
    glBindImageTexture(BIND_IMG_VPL_DEBUG_IDS, mIds.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    const GLuint zero = 0;
    glClearTexImage(mIds.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    if (view != VPL_DEBUG_VISIBILITY && in.vplCount > 0) {
        // Discs of about 1/100 of the image's height: visible, and apart at 1024 VPLs.
        const int radius = std::max(2, std::min(size.x, size.y) / 100);
        glProgramUniform1i(mSplat.id(), LOC_VPL_DEBUG_HIGHLIGHT,
                view == VPL_DEBUG_SUBSET ? in.highlightClass : -1);
        glProgramUniform1i(mSplat.id(), LOC_VPL_DEBUG_RADIUS, radius);
        glUseProgram(mSplat.id());
        glDispatchCompute(GLuint((in.vplCount + 63) / 64), 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glProgramUniform1i(mCompose.id(), LOC_VPL_DEBUG_VIEW, view);
    glUseProgram(mCompose.id());
    glBindTextureUnit(BIND_TEX_VPL_GATHERED, in.merged.id());
    glBindImageTexture(BIND_IMG_VPL_DEBUG_TARGET, mImage.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
            GL_RGBA32F);
    const glm::ivec2 groups = (size + VPL_LOCAL_SIZE - 1) / VPL_LOCAL_SIZE;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    // The renderer copies the image into its target.
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::vpl
