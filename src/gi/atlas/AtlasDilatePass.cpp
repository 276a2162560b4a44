#include "gi/atlas/AtlasDilatePass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasDilatePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    return mPass.init(shaders, "atlas/dilate", "atlas/dilate.frag", error) &&
           mMaskPass.init(shaders, "atlas/surface_mask", "atlas/surface_mask.frag", error);
}

bool AtlasDilatePass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    return gl::attachFramebuffer(mFramebuffer, "atlas/dilate", {&textures.lit, textures.attachable(textures.litBack)}, nullptr, error) &&
           gl::attachFramebuffer(mMaskFramebuffer, "atlas/surface_mask",
                   {&textures.surfaceMask}, nullptr, error);
}

void AtlasDilatePass::drawSurfaceMask(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/surface_mask");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_NORMAL, in.textures.normal.id());
    glBindTextureUnit(BIND_TEX_ATLAS_POSITION, in.textures.position.id());
    mMaskPass.draw(mMaskFramebuffer, mResolution);
}

void AtlasDilatePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    (void)out;   // textures.lit is attached to mFramebuffer
    gl::GpuScope scope(profiler, "atlas/dilate");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_SUMS, in.textures.sumsOf(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_SUMS_BACK, in.textures.sumsBackOf(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_SURFACE_MASK, in.textures.surfaceMask.id());
    mPass.draw(mFramebuffer, mResolution);
}

} // namespace gi::atlas
