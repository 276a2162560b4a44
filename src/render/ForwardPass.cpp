#include "render/ForwardPass.h"

#include "gl/Shared.h"

namespace gi::render {

bool ForwardPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    if (!mPrograms.init(shaders, {"render/forward",
                {{GL_VERTEX_SHADER, "render/forward.vert"},
                 {GL_FRAGMENT_SHADER, "render/forward.frag"}}, {}}, error)) {
        return false;
    }
    mDepthProgram = shaders.build({"render/depth_prepass",
            {{GL_VERTEX_SHADER, "render/forward.vert"}, {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    return bool(mDepthProgram);
}

void ForwardPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "render/forward");
    out.target.bind();
    out.target.clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);

    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    in.scene.bindLights();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    if (in.depthPrepass) in.scene.drawDepthPrepass(mDepthProgram.id());
    const GLuint program = mPrograms.id(in.switches.defines());
    glUseProgram(program);
    const glm::vec2 indirectSize = in.indirect ? glm::vec2(in.indirectSize) : glm::vec2(0.0f);
    glProgramUniform2fv(program, LOC_FORWARD_INDIRECT_SIZE, 1, &indirectSize[0]);
    glBindTextureUnit(BIND_TEX_INDIRECT, in.indirect ? in.indirect->id() : 0);
    const bool specular = in.indirect && in.indirectSpecular;
    glProgramUniform1i(program, LOC_FORWARD_INDIRECT_SPECULAR, specular ? 1 : 0);
    glBindTextureUnit(BIND_TEX_INDIRECT_SPECULAR, specular ? in.indirectSpecular->id() : 0);
    in.shadows.bind();
    in.scene.drawAll(program, true);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::render
