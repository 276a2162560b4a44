#include "render/ForwardPass.h"

#include "gl/Shared.h"

namespace gi::render {

bool ForwardPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"render/forward",
            {{GL_VERTEX_SHADER, "render/forward.vert"}, {GL_FRAGMENT_SHADER, "render/forward.frag"}},
            {}}, error);
    return bool(mProgram);
}

void ForwardPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "render/forward");
    glBindFramebuffer(GL_FRAMEBUFFER, out.target.id());
    glViewport(0, 0, out.size.x, out.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float clearColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float clearDepth = 1.0f;
    glClearNamedFramebufferfv(out.target.id(), GL_COLOR, 0, clearColor);
    glClearNamedFramebufferfv(out.target.id(), GL_DEPTH, 0, &clearDepth);

    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LIGHTS, in.scene.lightBuffer().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    in.shadows.bind();
    in.scene.drawAll(mProgram.id(), true);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::render
