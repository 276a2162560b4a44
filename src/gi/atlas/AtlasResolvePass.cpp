#include "gi/atlas/AtlasResolvePass.h"

#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasResolvePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"atlas/resolve",
                                     {{GL_VERTEX_SHADER, "atlas/resolve.vert"},
                                             {GL_FRAGMENT_SHADER, "atlas/resolve.frag"}},
                                     {}},
            error);
    return bool(mProgram);
}

void AtlasResolvePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    mTarget.resize(out.size);
    mSize = mTarget.size();
    gl::GpuScope scope(profiler, "atlas/resolve");
    mTarget.bind();
    mTarget.clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT, in.textures.lit.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT_BACK, in.textures.litBack.id());
    in.scene.drawAll(mProgram.id(), true, &in.geometry.vertexArray());
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
