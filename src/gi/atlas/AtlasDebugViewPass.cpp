#include "gi/atlas/AtlasDebugViewPass.h"

#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasDebugViewPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"atlas/debug_view",
                                     {{GL_VERTEX_SHADER, "atlas/resolve.vert"},
                                             {GL_FRAGMENT_SHADER, "atlas/debug_view.frag"}},
                                     {}},
            error);
    return bool(mProgram);
}

void AtlasDebugViewPass::execute(const Inputs& in, const Outputs& out,
        gl::GpuProfiler& profiler) {
    mTarget.resize(out.size);
    gl::GpuScope scope(profiler, "atlas/debug_view");
    mTarget.bind();
    mTarget.clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, in.textures.direct.id());
    glBindTextureUnit(BIND_TEX_ATLAS_NORMAL, in.textures.normal.id());
    glBindTextureUnit(BIND_TEX_ATLAS_POSITION, in.textures.position.id());
    glBindTextureUnit(BIND_TEX_ATLAS_ALBEDO, in.textures.albedo.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT, in.textures.lit.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, in.textures.directBack.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT_BACK, in.textures.litBack.id());
    in.scene.drawAll(mProgram.id(), true, &in.geometry.vertexArray());
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
