#include "gi/voxel/EmptyDistancePass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool EmptyDistancePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/empty_distance",
            {{GL_COMPUTE_SHADER, "voxel/empty_distance.comp"}}, {}}, error);
    return bool(mProgram);
}

void EmptyDistancePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    gl::GpuScope scope(profiler, "voxel/empty_distance");
    // Waits for the passes before it: with a memory barrier alone llvmpipe let it read the
    // normals while voxelization was still writing them (the image changed from run to run).
    glFinish();
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindImageTexture(BIND_IMG_VOXEL_NORMAL, t.normal.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
            GL_RGBA8_SNORM);
    glBindImageTexture(BIND_IMG_VOXEL_DISTANCE_X, t.distanceScratch[0].id(), 0, GL_TRUE, 0,
            GL_READ_WRITE, GL_R8UI);
    glBindImageTexture(BIND_IMG_VOXEL_DISTANCE_XY, t.distanceScratch[1].id(), 0, GL_TRUE, 0,
            GL_READ_WRITE, GL_R8UI);
    const GLuint groups = GLuint((t.resolution + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
    for (int axis = 0; axis < 3; ++axis) {
        // Producers: voxelization and propagation (the first), the previous axis (the others).
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glProgramUniform1i(mProgram.id(), LOC_VOXEL_LEVEL, axis);
        glDispatchCompute(groups, groups, groups);
    }
    // Consumer: cone tracing (and the voxels' bounce gather) fetch the normals. It waits
    // too: with the barrier alone llvmpipe's trace read texels the pass was still writing.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glFinish();
    glUseProgram(0);
}

} // namespace gi::voxel
