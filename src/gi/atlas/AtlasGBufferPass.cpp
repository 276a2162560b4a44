#include "gi/atlas/AtlasGBufferPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasGBufferPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mExact = shaders.build({"atlas/gbuffer",
                                   {{GL_VERTEX_SHADER, "atlas/gbuffer.vert"},
                                           {GL_FRAGMENT_SHADER, "atlas/gbuffer.frag"}},
                                   {}},
            error);
    if (!mExact) return false;
    mConservative = shaders.build({"atlas/gbuffer_conservative",
                                          {{GL_VERTEX_SHADER, "atlas/gbuffer.vert"},
                                                  {GL_GEOMETRY_SHADER, "atlas/gbuffer.geom"},
                                                  {GL_FRAGMENT_SHADER, "atlas/gbuffer.frag"}},
                                          {"CONSERVATIVE"}},
            error);
    if (!mConservative) return false;
    mArea = shaders.build({"atlas/gbuffer_area",
                                  {{GL_VERTEX_SHADER, "atlas/gbuffer.vert"},
                                          {GL_GEOMETRY_SHADER, "atlas/gbuffer.geom"},
                                          {GL_FRAGMENT_SHADER, "atlas/gbuffer.frag"}},
                                  {"CONSERVATIVE", "SAMPLE_AREA"}},
            error);
    return bool(mArea);
}

bool AtlasGBufferPass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    mDepth = gl::createTexture2D(
            GL_DEPTH_COMPONENT32F, {mResolution, mResolution}, 1, "atlas/gbuffer_depth");
    return gl::attachFramebuffer(mFramebuffer, "atlas/gbuffer",
            {&textures.direct, &textures.normal, &textures.position, &textures.albedo,
                    textures.attachable(textures.directBack)},
            &mDepth, error);
}

void AtlasGBufferPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/gbuffer");
    (void)out;
    const GLuint fbo = mFramebuffer.id();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float clearDepth = 1.0f;
    for (int i = 0; i < 5; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &clearDepth);

    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    in.scene.bindLights();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    in.shadows.bind();
    // Triangles may land in the atlas with either winding: no culling in either draw.
    glUseProgram(mExact.id());
    in.scene.drawAll(mExact.id(), false, &in.geometry.vertexArray());
    glUseProgram(mConservative.id());
    in.scene.drawAll(mConservative.id(), false, &in.geometry.vertexArray());
    // Sample areas: every triangle adds its area inside each texel it touches to position.w.
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glColorMaski(2, GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glEnablei(GL_BLEND, 2);
    glBlendEquationi(2, GL_FUNC_ADD);
    glBlendFunci(2, GL_ONE, GL_ONE);
    glUseProgram(mArea.id());
    in.scene.drawAll(mArea.id(), false, &in.geometry.vertexArray());
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
