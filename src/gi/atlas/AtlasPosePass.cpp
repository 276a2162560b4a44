#include "gi/atlas/AtlasPosePass.h"

#include "gl/Shared.h"

namespace gi::atlas {

bool AtlasPosePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"atlas/follow_pose", {{GL_COMPUTE_SHADER, "atlas/follow_pose.comp"}}, {}},
            error);
    return bool(mProgram);
}

void AtlasPosePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const AtlasGeometry& geometry = out.geometry;
    if (!geometry.sources() || geometry.vertexCount() == 0) return;
    gl::GpuScope scope(profiler, "atlas/follow-pose");
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SCENE_VERTICES, in.scene.vertexBuffer().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_VERTICES, geometry.vertexBuffer().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_SOURCES, geometry.sources().id());
    const auto groups = GLuint((geometry.vertexCount() + ATLAS_POSE_LOCAL_SIZE - 1) / ATLAS_POSE_LOCAL_SIZE);
    glDispatchCompute(groups, 1, 1);
    // Consumers: every atlas pass draws these vertices.
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::atlas
