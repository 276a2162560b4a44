#include "gi/vpl/VplBouncePass.h"

namespace gi::vpl {

bool VplBouncePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"vpl/bounce", {{GL_COMPUTE_SHADER, "vpl/bounce.comp"}}, {}}, error);
    return bool(mProgram);
}

std::vector<shader::GpuVpl> VplBouncePass::execute(const std::vector<shader::GpuVpl>& parents,
        int rays, const OccupancyVolume& occupancy, gl::GpuProfiler& profiler) {
    std::vector<shader::GpuVpl> children;
    if (parents.empty() || rays <= 0) return children;
    gl::GpuScope scope(profiler, "vpl/bounce");
    const gl::Buffer parentBuffer = gl::createBuffer(parents.size() * sizeof(shader::GpuVpl),
            parents.data(), 0, "vpl/bounce_parents");
    const std::size_t bytes = std::size_t(rays) * sizeof(shader::GpuVpl);
    const gl::Buffer hits = gl::createBuffer(bytes, nullptr, 0, "vpl/bounce_hits");
    glUseProgram(mProgram.id());
    glProgramUniform2i(mProgram.id(), LOC_VPL_BOUNCE_COUNTS, GLint(parents.size()), rays);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_VPLS, parentBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_VPL_BOUNCES, hits.id());
    occupancy.bind();
    glDispatchCompute(GLuint((rays + VPL_BOUNCE_LOCAL_SIZE - 1) / VPL_BOUNCE_LOCAL_SIZE), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    std::vector<shader::GpuVpl> rayEnds(static_cast<std::size_t>(rays));
    glGetNamedBufferSubData(hits.id(), 0, GLsizeiptr(bytes), rayEnds.data());
    children.reserve(rayEnds.size());
    for (const shader::GpuVpl& vpl : rayEnds) {
        if (vpl.flux.r + vpl.flux.g + vpl.flux.b > 0.0f) children.push_back(vpl);
    }
    return children;
}

} // namespace gi::vpl
