#include "gi/voxel/PropagatePass.h"

#include "gi/voxel/LevelDispatch.h"
#include "gl/Shared.h"

namespace gi::voxel {

bool PropagatePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/propagate", {{GL_COMPUTE_SHADER, "voxel/propagate.comp"}}, {}},
            error);
    return bool(mProgram);
}

void PropagatePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    if (t.levels < 2) return;
    gl::GpuScope scope(profiler, "voxel/propagate");
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindImageTexture(BIND_IMG_VOXEL_ALBEDO, t.albedo.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_NORMAL, t.normal.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA8_SNORM);
    glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, t.irradiance.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    const GLuint groups = GLuint((t.resolution / 2 + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
    dispatchLevelByLevel(mProgram.id(), groups, 1, t.levels);
}

} // namespace gi::voxel
