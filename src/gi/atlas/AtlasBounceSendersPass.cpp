#include "gi/atlas/AtlasBounceSendersPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasBounceSendersPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    return mPass.init(shaders, "atlas/bounce_senders", "atlas/bounce_senders.frag", error);
}

bool AtlasBounceSendersPass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    if (textures.bounceCount() == 1) return true;
    return gl::attachFramebuffer(mFramebuffer, "atlas/bounce_senders",
            {&textures.senders, textures.attachable(textures.sendersBack)}, nullptr, error);
}

void AtlasBounceSendersPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/bounce_senders");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, in.textures.direct.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, in.textures.directBack.id());
    glBindTextureUnit(BIND_TEX_ATLAS_ALBEDO, in.textures.albedo.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT, in.textures.lit.id());
    glBindTextureUnit(BIND_TEX_ATLAS_LIT_BACK, in.textures.litBack.id());
    mPass.draw(mFramebuffer, mResolution);
}

} // namespace gi::atlas
