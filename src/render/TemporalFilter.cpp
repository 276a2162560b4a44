#include "render/TemporalFilter.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <algorithm>
#include <cmath>

namespace gi::render {

bool TemporalFilter::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"render/temporal_filter",
            {{GL_COMPUTE_SHADER, "render/temporal_filter.comp"}}, {}}, error);
    return bool(mProgram);
}

int TemporalFilter::fadeFrames(float blend) {
    // The history's share of the light from before the step after n frames: (1 - blend)^n.
    const float keep = std::clamp(1.0f - blend, 0.0f, 0.999f);
    if (keep <= kResampleResidue) return 1;
    return int(std::ceil(std::log(kResampleResidue) / std::log(keep)));
}

const gl::Texture& TemporalFilter::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    if (in.size != mSize) {
        mSize = in.size;
        for (int i = 0; i < 2; ++i) {
            // 32-bit: a half-float history stalls a few units of the last place (0.1 % each)
            // away from a still image, where blend x difference rounds back to no change.
            mIrradiance[i] = gl::createTargetTexture(
                    {GL_RGBA32F, "render/temporal_irradiance", true}, mSize);
            mNormal[i] =
                    gl::createTargetTexture({GL_RGBA16F, "render/temporal_normal", true}, mSize);
        }
        mHasHistory = false;
    }
    gl::GpuScope scope(profiler, "render/temporal_filter");
    const int previous = 1 - mCurrent;
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindTextureUnit(BIND_TEX_TEMPORAL_CURRENT, in.indirect.id());
    glBindTextureUnit(BIND_TEX_TEMPORAL_HISTORY, mIrradiance[previous].id());
    glBindTextureUnit(BIND_TEX_TEMPORAL_HISTORY_NORMAL, mNormal[previous].id());
    glBindImageTexture(BIND_IMG_TEMPORAL_TARGET, mIrradiance[mCurrent].id(), 0, GL_FALSE, 0,
            GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(BIND_IMG_TEMPORAL_NORMAL, mNormal[mCurrent].id(), 0, GL_FALSE, 0,
            GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint program = mProgram.id();
    glProgramUniformMatrix4fv(program, LOC_TEMPORAL_PREVIOUS_VIEW_PROJECTION, 1, GL_FALSE,
            &mPreviousViewProjection[0][0]);
    glProgramUniformMatrix4fv(program, LOC_TEMPORAL_PREVIOUS_VIEW, 1, GL_FALSE,
            &mPreviousView[0][0]);
    // A resampled technique's step is no change of the light: clipping the history to the new
    // frame would show it at once (a voxel cascade's snap moved the Sponza walk's indirect
    // light by 29.5 % in one frame, against 17.1 % on the others), so the exponential average
    // fades it in while the history still holds the light from before it.
    // While the geometry moves the light changes a little every frame, too little for the clip
    // to catch: the moving cube's light lagged four frames behind it at a weight of 0.2.
    const float blend = in.geometryMoved ? std::max(in.settings.blend, in.settings.blendMoving)
                                         : in.settings.blend;
    if (in.resampled && mHasHistory) mUnclippedFrames = fadeFrames(blend);
    const bool clip = in.settings.clamp && mUnclippedFrames == 0;
    mUnclippedFrames = std::max(mUnclippedFrames - 1, 0);
    const glm::vec4 parameters(blend, mHasHistory ? 1.0f : 0.0f,
            clip ? 1.0f : 0.0f, 0.0f);
    glProgramUniform4fv(program, LOC_TEMPORAL_PARAMETERS, 1, &parameters[0]);
    const glm::ivec2 groups = (mSize + TEMPORAL_LOCAL_SIZE - 1) / TEMPORAL_LOCAL_SIZE;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    // Consumers: the forward pass samples the result, the next frame's filter the history.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);

    mPreviousViewProjection = in.camera.viewProjection();
    mPreviousView = in.camera.view;
    mHasHistory = true;
    const gl::Texture& result = mIrradiance[mCurrent];
    mCurrent = previous;
    return result;
}

} // namespace gi::render
