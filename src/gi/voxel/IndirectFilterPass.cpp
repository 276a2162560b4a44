#include "gi/voxel/IndirectFilterPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <algorithm>
#include <string>

namespace gi::voxel {

bool IndirectFilterPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    return mPrograms.init(shaders, {"voxel/indirect_filter",
            {{GL_COMPUTE_SHADER, "voxel/indirect_filter.comp"}}, {}}, error);
}

void IndirectFilterPass::execute(const Inputs& in, const Outputs& out,
        gl::GpuProfiler& profiler) {
    const glm::ivec2 size = out.size;
    if (size != mSize) {
        mSize = size;
        mResult = gl::createTargetTexture({GL_RGBA16F, "voxel/indirect_filtered", true}, size);
    }
    gl::GpuScope scope(profiler, "voxel/filter");
    const int radius = std::clamp(in.radius, 1, VOXEL_FILTER_MAX_RADIUS);
    glUseProgram(mPrograms.id({"FILTER_RADIUS " + std::to_string(radius)}));
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindTextureUnit(BIND_TEX_FILTER_SOURCE, in.source.id());
    glBindImageTexture(BIND_IMG_FILTER_TARGET, mResult.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const glm::ivec2 groups = (size + VOXEL_FILTER_LOCAL_SIZE - 1) / VOXEL_FILTER_LOCAL_SIZE;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    // Consumer: the forward pass samples the result.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
