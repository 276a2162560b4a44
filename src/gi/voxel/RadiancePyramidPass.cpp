#include "gi/voxel/RadiancePyramidPass.h"

#include "gl/Shared.h"

#include <algorithm>

namespace gi::voxel {

bool RadiancePyramidPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/radiance_pyramid",
            {{GL_COMPUTE_SHADER, "voxel/radiance_pyramid.comp"}}, {}}, error);
    mDirectionalProgram = shaders.build({"voxel/directional_pyramid",
            {{GL_COMPUTE_SHADER, "voxel/directional_pyramid.comp"}}, {}}, error);
    return mProgram && mDirectionalProgram;
}

void RadiancePyramidPass::execute(const Inputs& in, const Outputs& out,
        gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    gl::GpuScope scope(profiler, "voxel/pyramid");
    const GLuint program = t.anisotropic ? mDirectionalProgram.id() : mProgram.id();
    glUseProgram(program);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    if (t.anisotropic) {
        glBindImageTexture(BIND_IMG_VOXEL_DIRECTIONAL, in.cascade.directional.id(), 0, GL_TRUE,
                0, GL_READ_ONLY, GL_RGBA16F);
    } else {
        glBindImageTexture(BIND_IMG_VOXEL_ALBEDO, in.cascade.albedo.id(), 0, GL_TRUE, 0,
                GL_READ_ONLY, GL_RGBA16F);
        glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, in.cascade.irradiance.id(), 0, GL_TRUE, 0,
                GL_READ_ONLY, GL_RGBA16F);
        glBindImageTexture(BIND_IMG_VOXEL_NORMAL, in.cascade.normal.id(), 0, GL_TRUE, 0,
                GL_READ_ONLY, GL_RGBA8_SNORM);
    }
    for (int mip = 0; mip < t.pyramidLevels(); ++mip) {
        // Mip 0 reads the cascade; the source binding is then unused but still valid.
        glBindImageTexture(BIND_IMG_VOXEL_PYRAMID_SOURCE, t.pyramid.id(), mip > 0 ? mip - 1 : 0,
                GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
        glBindImageTexture(BIND_IMG_VOXEL_PYRAMID, t.pyramid.id(), mip, GL_TRUE, 0, GL_WRITE_ONLY,
                GL_RGBA16F);
        glProgramUniform1i(program, LOC_VOXEL_LEVEL, mip);
        const int size = std::max(t.resolution / (2 << mip), 1);
        const GLuint groups = GLuint((size + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
        glDispatchCompute(groups, groups, groups);
        // Consumer: the next mip reads this one.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    // Consumer: cone tracing samples the pyramid.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
