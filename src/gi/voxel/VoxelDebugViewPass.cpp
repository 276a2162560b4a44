#include "gi/voxel/VoxelDebugViewPass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool VoxelDebugViewPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"voxel/debug_view",
            {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "voxel/debug_view.frag"}},
            {}}, error);
    mEmpty = gl::createVertexArray("voxel/debug_view");
    return bool(mProgram);
}

void VoxelDebugViewPass::execute(const Inputs& in, const Outputs& out,
        gl::GpuProfiler& profiler) {
    mTarget.resize(out.size);
    gl::GpuScope scope(profiler, "voxel/debug_view");
    mTarget.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(mProgram.id());
    glProgramUniform1i(mProgram.id(), LOC_VOXEL_LEVEL, in.level);
    glProgramUniform1i(mProgram.id(), LOC_VOXEL_DEBUG_VIEW, int(in.view));
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, in.textures.albedo.id());
    glBindTextureUnit(BIND_TEX_VOXEL_IRRADIANCE, in.textures.irradiance.id());
    glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, in.textures.normal.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::voxel
