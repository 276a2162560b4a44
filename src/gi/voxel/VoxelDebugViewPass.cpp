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

void VoxelDebugViewPass::execute(const gl::Buffer& frameUniforms, const gl::Buffer& voxelUniforms,
        const VoxelTextures& textures, glm::ivec2 size, gl::GpuProfiler& profiler) {
    if (size != mSize) {
        mSize = size;
        mImage = gl::createTexture2D(GL_RGBA32F, size, 1, "voxel/debug_view");
        mFramebuffer = gl::createFramebuffer("voxel/debug_view");
        glNamedFramebufferTexture(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, mImage.id(), 0);
    }
    gl::GpuScope scope(profiler, "voxel/debug_view");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, voxelUniforms.id());
    glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, textures.albedo.id());
    glBindTextureUnit(BIND_TEX_VOXEL_IRRADIANCE, textures.irradiance.id());
    glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, textures.normal.id());
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::voxel
