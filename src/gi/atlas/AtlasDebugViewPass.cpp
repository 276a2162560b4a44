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

void AtlasDebugViewPass::execute(const Inputs& in, glm::ivec2 size, gl::GpuProfiler& profiler) {
    if (size != mSize) {
        mSize = size;
        mImage = gl::createTexture2D(GL_RGBA32F, size, 1, "atlas/debug_view");
        mDepth = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size, 1, "atlas/debug_view_depth");
        mFramebuffer = gl::createFramebuffer("atlas/debug_view");
        glNamedFramebufferTexture(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, mImage.id(), 0);
        glNamedFramebufferTexture(mFramebuffer.id(), GL_DEPTH_ATTACHMENT, mDepth.id(), 0);
    }
    gl::GpuScope scope(profiler, "atlas/debug_view");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, size.x, size.y);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float clearDepth = 1.0f;
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &clearDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
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
    in.scene.drawAll(mProgram.id(), true, &in.geometry.vertexArray());
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
