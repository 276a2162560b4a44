#include "gi/atlas/AtlasDilatePass.h"

#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasDilatePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"atlas/dilate",
                                     {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                                             {GL_FRAGMENT_SHADER, "atlas/dilate.frag"}},
                                     {}},
            error);
    mEmpty = gl::createVertexArray("atlas/dilate");
    return bool(mProgram);
}

bool AtlasDilatePass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    mFramebuffer = gl::createFramebuffer("atlas/dilate");
    glNamedFramebufferTexture(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, textures.lit.id(), 0);
    return gl::framebufferComplete(mFramebuffer, "atlas/dilate", error);
}

void AtlasDilatePass::execute(
        const AtlasTextures& textures, const gl::Buffer& atlasUniforms, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/dilate");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_SUMS, textures.sums.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
