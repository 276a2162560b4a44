#include "gi/voxel/DirectionalVoxelsPass.h"

#include "gi/voxel/LevelDispatch.h"
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
    dispatchLevelByLevel(mProgram.id(), groups, 0, t.levels);
}

} // namespace gi::voxel
