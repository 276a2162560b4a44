#include "gi/voxel/EmptyBlocksPass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool EmptyBlocksPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/empty_blocks",
            {{GL_COMPUTE_SHADER, "voxel/empty_blocks.comp"}}, {}}, error);
    return bool(mProgram);
}

void EmptyBlocksPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    // Anisotropic voxels' walk never crosses blocks (cone_tracing.glsl).
    if (t.anisotropic) return;
    gl::GpuScope scope(profiler, "voxel/empty_blocks");
    // Producers: voxelization and propagation wrote the normals as images.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindImageTexture(BIND_IMG_VOXEL_NORMAL, t.normal.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
            GL_RGBA8_SNORM);
    // voxel.resolution is a power of two of at least 4 (VoxelizationManager::configure).
    const int blocks = t.resolution / VOXEL_BLOCK;
    const GLuint groups = GLuint((blocks + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
    glDispatchCompute(groups, groups, groups);
    // Consumer: cone tracing (and the voxels' bounce gather) fetch the normals.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
