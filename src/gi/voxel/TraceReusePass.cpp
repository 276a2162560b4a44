#include "gi/voxel/TraceReusePass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool TraceReusePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/trace_reuse",
            {{GL_COMPUTE_SHADER, "voxel/trace_reuse.comp"}}, {}}, error);
    if (!mProgram) return false;
    // The cone trace's own vertex stage, so the depths match the trace's surfaces.
    mDepthProgram = shaders.build({"voxel/trace_reuse_depth",
            {{GL_VERTEX_SHADER, "voxel/cone_trace.vert"},
             {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    return bool(mDepthProgram);
}

void TraceReusePass::drawDepth(const Inputs& in) {
    mDepth.resize(mSize);
    mDepth.bind();
    mDepth.clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS,
            in.scene.materialBuffer().id());
    glProgramUniform2f(mDepthProgram.id(), LOC_CONE_TRACE_OFFSET, 0.0f, 0.0f);
    in.scene.drawDepthPrepass(mDepthProgram.id());
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void TraceReusePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    if (out.size != mSize) {
        mSize = out.size;
        for (gl::Texture& result : mResult) {
            result = gl::createTargetTexture({GL_RGBA16F, "voxel/reuse_indirect", true}, mSize);
        }
        mHasHistory = false;
    }
    gl::GpuScope scope(profiler, "voxel/trace_reuse");
    if (in.stride == 2) drawDepth(in);
    const GLuint program = mProgram.id();
    glUseProgram(program);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindTextureUnit(BIND_TEX_REUSE_TRACED, in.traced.id());
    glBindTextureUnit(BIND_TEX_REUSE_DEPTH, mDepth.depth().id());
    glBindTextureUnit(BIND_TEX_REUSE_HISTORY, mResult[1 - mCurrent].id());
    glBindImageTexture(BIND_IMG_REUSE_TARGET, mResult[mCurrent].id(), 0, GL_FALSE, 0,
            GL_WRITE_ONLY, GL_RGBA16F);
    glProgramUniformMatrix4fv(program, LOC_REUSE_PREVIOUS_VIEW_PROJECTION, 1, GL_FALSE,
            &mPreviousViewProjection[0][0]);
    glProgramUniformMatrix4fv(program, LOC_REUSE_PREVIOUS_VIEW, 1, GL_FALSE,
            &mPreviousView[0][0]);
    glProgramUniform4i(program, LOC_REUSE_PHASE, in.phase.x, in.phase.y, mHasHistory ? 1 : 0,
            in.stride);
    const glm::ivec2 groups = (mSize + TRACE_REUSE_LOCAL_SIZE - 1) / TRACE_REUSE_LOCAL_SIZE;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    // Consumers: the indirect filter and the forward pass sample it, the next frame reads it
    // as history.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);

    mPreviousViewProjection = in.camera.viewProjection();
    mPreviousView = in.camera.view;
    mHasHistory = true;
    mCurrent = 1 - mCurrent;
}

} // namespace gi::voxel
