#include "gi/atlas/AtlasGatherPass.h"

#include "gl/LoopBudget.h"
#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <algorithm>
#include <utility>

namespace gi::atlas {

bool AtlasGatherPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    // One shader, compiled once per way of testing visibility.
    auto gather = [&](const char* name, std::vector<std::string> defines) {
        return shaders.build({name,
                                     {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                                             {GL_FRAGMENT_SHADER, "atlas/gather.frag"}},
                                     std::move(defines)},
                error);
    };
    mProgram = gather("atlas/gather", {});
    if (!mProgram) return false;
    mVoxelProgram = gather("atlas/gather_voxel", {"VISIBILITY_VOXEL"});
    if (!mVoxelProgram) return false;
    mBvhProgram = gather("atlas/gather_bvh", {"VISIBILITY_BVH"});
    mEmpty = gl::createVertexArray("atlas/gather");
    return bool(mBvhProgram);
}

bool AtlasGatherPass::attach(const AtlasTextures& textures, std::string& error) {
    mResolution = textures.resolution;
    mFramebuffers.clear();
    for (int bounce = 0; bounce < textures.bounceCount(); ++bounce) {
        mFramebuffers.emplace_back();
        if (!gl::attachFramebuffer(mFramebuffers.back(), "atlas/gather",
                    {&textures.sumsOf(bounce), textures.attachable(textures.sumsBackOf(bounce))},
                    nullptr, error)) {
            return false;
        }
    }
    return true;
}

void AtlasGatherPass::clear() {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (const gl::Framebuffer& framebuffer : mFramebuffers) {
        glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 1, zero);
    }
}

void AtlasGatherPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    (void)out;   // textures.sumsOf(bounce) is attached to mFramebuffers[bounce]
    gl::GpuScope scope(profiler, "atlas/gather");
    const bool bvh = in.bvhRayIterations > 0;
    const GLuint program = bvh ? mBvhProgram.id() : in.occupancy ? mVoxelProgram.id() : mProgram.id();
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffers[std::size_t(in.bounce)].id());
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    // Sums add up; alpha (receiver written) stays 1.
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MAX);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    glUseProgram(program);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, in.textures.senderRadiance(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, in.textures.senderRadianceBack(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_NORMAL, in.textures.normal.id());
    glBindTextureUnit(BIND_TEX_ATLAS_POSITION, in.textures.position.id());
    glBindTextureUnit(BIND_TEX_ATLAS_SAMPLES, in.samples.id());
    in.senderSampling.bind();
    if (in.occupancy && !bvh) {
        in.occupancy->bind();
    }
    glBindVertexArray(mEmpty.id());
    // A sample walks one segment or ray; a sky direction one for each side of a double-sided
    // receiver.
    const int segment = bvh ? in.bvhRayIterations
                            : in.occupancy ? in.occupancy->visibilityLoopIterations() : 0;
    glProgramUniform4i(program, LOC_ATLAS_NEAR_RANGE, 0, 0, 0, 0);
    for (const glm::ivec2& sky : gl::rangesWithinLoopBudget(in.skyDirections, 2 * (1 + segment))) {
        glProgramUniform4i(program, LOC_ATLAS_GATHER_RANGE, 0, 0, sky.x, sky.y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    if (in.nearRays > 0 && in.bvhNodes > 0 && in.geometry) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_VERTICES, in.geometry->vertexBuffer().id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_INDICES, in.geometry->indexBuffer().id());
        // A ray's walk: its nodes, each leaf's triangles; for each side of a double-sided
        // receiver.
        const int nodes = std::min(in.bvhNodes, kNearRayNodes);
        const int walk = nodes * (1 + BVH_MAX_LEAF_TRIANGLES);
        glProgramUniform4i(program, LOC_ATLAS_GATHER_RANGE, 0, 0, 0, 0);
        for (const glm::ivec2& near : gl::rangesWithinLoopBudget(in.nearRays, 2 * (1 + walk))) {
            glProgramUniform4i(program, LOC_ATLAS_NEAR_RANGE, near.x, near.y, nodes, 0);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glProgramUniform4i(program, LOC_ATLAS_NEAR_RANGE, 0, 0, 0, 0);
    }
    for (const glm::ivec2& samples : gl::rangesWithinLoopBudget(in.sampleCount, 1 + segment)) {
        glProgramUniform4i(program, LOC_ATLAS_GATHER_RANGE, samples.x, samples.y, 0, 0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::atlas
