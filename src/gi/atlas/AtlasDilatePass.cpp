#include "gi/atlas/AtlasDilatePass.h"

#include "gl/RenderTarget.h"
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
    return gl::attachFramebuffer(mFramebuffer, "atlas/dilate", {&textures.lit, textures.attachable(textures.litBack)}, nullptr, error);
}

void AtlasDilatePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    (void)out;   // textures.lit is attached to mFramebuffer
    gl::GpuScope scope(profiler, "atlas/dilate");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_SUMS, in.textures.sumsOf(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_SUMS_BACK, in.textures.sumsBackOf(in.bounce).id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
