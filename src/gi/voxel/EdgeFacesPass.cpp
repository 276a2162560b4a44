#include "gi/voxel/EdgeFacesPass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool EdgeFacesPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/edge_faces",
            {{GL_COMPUTE_SHADER, "voxel/edge_faces.comp"}}, {}}, error);
    return bool(mProgram);
}

void EdgeFacesPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    gl::GpuScope scope(profiler, "voxel/edge_faces");
    // Producers: voxelization and propagation wrote the normals through images. It waits for
    // them, as EmptyDistancePass does: with a barrier alone llvmpipe let a pass read normals
    // still being written.
    glFinish();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, t.normal.id());
    glBindImageTexture(BIND_IMG_VOXEL_EDGE_FACES, t.edgeFaces.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
            GL_RGBA8_SNORM);
    const GLuint groups = GLuint((t.resolution + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE);
    glDispatchCompute(groups, groups, groups);
    // Consumers: the atlas' and the VPLs' marches fetch the faces.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glFinish();
    glUseProgram(0);
}

} // namespace gi::voxel
