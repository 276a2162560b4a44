#include "gi/voxel/VoxelizePass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool VoxelizePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/voxelize",
            {{GL_VERTEX_SHADER, "voxel/voxelize.vert"}, {GL_GEOMETRY_SHADER, "voxel/voxelize.geom"},
                    {GL_FRAGMENT_SHADER, "voxel/voxelize.frag"}},
            {}}, error);
    mFramebuffer = gl::createFramebuffer("voxel/voxelize");
    return bool(mProgram);
}

void VoxelizePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "voxel/voxelize");
    if (mSize != in.rasterSize || mSamples != in.samples) {
        mSize = in.rasterSize;
        mSamples = in.samples;
        glNamedFramebufferParameteri(mFramebuffer.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, mSize);
        glNamedFramebufferParameteri(mFramebuffer.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, mSize);
        glNamedFramebufferParameteri(mFramebuffer.id(), GL_FRAMEBUFFER_DEFAULT_SAMPLES,
                mSamples > 1 ? mSamples : 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mSize, mSize);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    glBindImageTexture(BIND_IMG_VOXEL_ALBEDO, out.textures.albedo.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_NORMAL, out.textures.normal.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA8_SNORM);
    glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, out.textures.irradiance.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_LOCK, out.textures.lock.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    if (out.textures.anisotropic) {
        glBindImageTexture(BIND_IMG_VOXEL_DIRECTIONAL, out.textures.directional.id(), 0, GL_TRUE,
                0, GL_READ_WRITE, GL_RGBA16F);
    }
    in.scene.drawAll(mProgram.id(), false, nullptr, in.draws);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // Consumers: light injection (lock), propagation (images), cone tracing (textures), the
    // static cache's copies (StaticVoxelCache::save).
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
            GL_TEXTURE_UPDATE_BARRIER_BIT);
}

} // namespace gi::voxel
