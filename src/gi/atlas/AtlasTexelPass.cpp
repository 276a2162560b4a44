#include "gi/atlas/AtlasTexelPass.h"

namespace gi::atlas {

bool AtlasTexelPass::init(gl::ShaderLibrary& shaders, const char* name,
        const char* fragmentShader, std::string& error) {
    mProgram = shaders.build({name,
                                     {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                                             {GL_FRAGMENT_SHADER, fragmentShader}},
                                     {}},
            error);
    mEmpty = gl::createVertexArray(name);
    return bool(mProgram);
}

void AtlasTexelPass::draw(const gl::Framebuffer& framebuffer, int resolution) const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, resolution, resolution);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
