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

void AtlasResolvePass::resize(glm::ivec2 size) {
    size = glm::max(size, glm::ivec2(1));
    if (size == mSize) return;
    mSize = size;
    mIndirect = gl::createTexture2D(GL_RGBA16F, size, 1, "atlas/indirect");
    glTextureParameteri(mIndirect.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(mIndirect.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(mIndirect.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mIndirect.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    mDepth = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size, 1, "atlas/resolve_depth");
    mFramebuffer = gl::createFramebuffer("atlas/resolve");
    glNamedFramebufferTexture(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, mIndirect.id(), 0);
    glNamedFramebufferTexture(mFramebuffer.id(), GL_DEPTH_ATTACHMENT, mDepth.id(), 0);
}

void AtlasResolvePass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/resolve");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mSize.x, mSize.y);
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
    glBindTextureUnit(BIND_TEX_ATLAS_LIT, in.textures.lit.id());
    in.scene.drawAll(mProgram.id(), true, &in.geometry.vertexArray());
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
