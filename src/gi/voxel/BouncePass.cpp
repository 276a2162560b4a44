#include "gi/voxel/BouncePass.h"

#include "gl/Shared.h"

namespace gi::voxel {

bool BouncePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mGather = shaders.build({"voxel/bounce_gather", {{GL_COMPUTE_SHADER, "voxel/bounce.comp"}},
            {"STEP_GATHER"}}, error);
    if (!mGather) return false;
    mApply = shaders.build({"voxel/bounce_apply", {{GL_COMPUTE_SHADER, "voxel/bounce.comp"}},
            {"STEP_APPLY"}}, error);
    return bool(mApply);
}

void BouncePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const VoxelTextures& t = out.textures;
    gl::GpuScope scope(profiler, "voxel/bounce");
    if (in.first) glClearTexImage(t.gathered.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    const glm::ivec3 size(t.resolution, t.resolution, t.resolution * t.levels);
    const glm::ivec3 groups = (size + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE;
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, t.albedo.id());
    glBindTextureUnit(BIND_TEX_VOXEL_IRRADIANCE, t.irradiance.id());
    glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, t.normal.id());
    glBindTextureUnit(BIND_TEX_VOXEL_PYRAMID, t.pyramid.id());
    glBindImageTexture(BIND_IMG_VOXEL_HELPER, t.helper.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
            GL_RGBA16F);
    glUseProgram(mGather.id());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    // Consumer: the apply step reads what was gathered.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, t.irradiance.id(), 0, GL_TRUE, 0,
            GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_GATHERED, t.gathered.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
            GL_RGBA16F);
    glUseProgram(mApply.id());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    // Consumers: propagation reads the irradiance as an image, the next gather samples it.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
