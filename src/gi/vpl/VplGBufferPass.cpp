#include "gi/vpl/VplGBufferPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <cstdio>

namespace gi::vpl {

bool VplGBufferPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mDepthProgram = shaders.build({"vpl/gbuffer_depth",
            {{GL_VERTEX_SHADER, "vpl/gbuffer.vert"},
             {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    if (!mDepthProgram) return false;
    mProgram = shaders.build({"vpl/gbuffer",
            {{GL_VERTEX_SHADER, "vpl/gbuffer.vert"}, {GL_FRAGMENT_SHADER, "vpl/gbuffer.frag"}},
            {}}, error);
    return bool(mProgram);
}

bool VplGBufferPass::resize(glm::ivec2 size) {
    size = glm::max(size, glm::ivec2(1));
    if (size == mSize) return true;
    mPosition = gl::createTargetTexture({GL_RGBA32F, "vpl/gbuffer_position"}, size);
    mNormal = gl::createTargetTexture({GL_RGBA16F, "vpl/gbuffer_normal"}, size);
    mDepth = gl::createTargetTexture({GL_DEPTH_COMPONENT32F, "vpl/gbuffer_depth"}, size);
    std::string error;
    if (!gl::attachFramebuffer(mFramebuffer, "vpl/gbuffer", {&mPosition, &mNormal}, &mDepth,
                error)) {
        std::fprintf(stderr, "vpl: %s\n", error.c_str());
        mSize = glm::ivec2(0);
        return false;
    }
    mSize = size;
    return true;
}

void VplGBufferPass::execute(const scene::GpuScene& scene, const gl::Buffer& frameUniforms,
        glm::ivec2 size, gl::GpuProfiler& profiler) {
    if (!resize(size)) return;
    gl::GpuScope scope(profiler, "vpl/gbuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mSize.x, mSize.y);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 1, zero);
    glDepthMask(GL_TRUE);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, frameUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, scene.materialBuffer().id());
    glDepthFunc(GL_LESS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mDepthProgram.id());
    scene.drawAll(mDepthProgram.id(), true);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(mProgram.id());
    scene.drawAll(mProgram.id(), true);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::vpl
