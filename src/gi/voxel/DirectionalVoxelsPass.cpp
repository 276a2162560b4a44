#include "gi/voxel/DirectionalVoxelsPass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool DirectionalVoxelsPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/directional_build",
            {{GL_COMPUTE_SHADER, "voxel/directional_build.comp"}}, {}}, error);
    return bool(mProgram);
}

void DirectionalVoxelsPass::execute(const Inputs& in, const Outputs& out,
        gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    gl::GpuScope scope(profiler, "voxel/directional");
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindImageTexture(BIND_IMG_VOXEL_ALBEDO, in.cascade.albedo.id(), 0, GL_TRUE, 0,
            GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, in.cascade.irradiance.id(), 0, GL_TRUE, 0,
            GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_DIRECTIONAL, t.directional.id(), 0, GL_TRUE, 0,
            GL_READ_WRITE, GL_RGBA16F);
    const GLuint groups = GLuint((t.resolution + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
    for (int level = 0; level < t.levels; ++level) {
        glProgramUniform1i(mProgram.id(), LOC_VOXEL_LEVEL, level);
        glDispatchCompute(groups, groups, groups);
        // Consumer: the next level composites this one's faces.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    // Consumers: the pyramid (image loads, covered above) and cone tracing's filtered reads.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
