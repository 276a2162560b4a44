#include "gi/atlas/AtlasBounceSendersPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasBounceSendersPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"atlas/bounce_senders",
                                     {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                                             {GL_FRAGMENT_SHADER, "atlas/bounce_senders.frag"}},
                                     {}},
            error);
    mEmpty = gl::createVertexArray("atlas/bounce_senders");
    return bool(mProgram);
}

bool AtlasBounceSendersPass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    if (textures.bounceCount() == 1) return true;
    return gl::attachFramebuffer(mFramebuffer, "atlas/bounce_senders",
            {&textures.senders, textures.attachable(textures.sendersBack)}, nullptr, error);
}

void AtlasBounceSendersPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/bounce_senders");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, in.textures.direct.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, in.textures.directBack.id());
    glBindTextureUnit(BIND_TEX_ATLAS_ALBEDO, in.textures.albedo.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT, in.textures.lit.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT_BACK, in.textures.litBack.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
