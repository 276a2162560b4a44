#include "gi/voxel/ConeTracePass.h"

#include "gl/Shared.h"

#include <cstdio>
#include <string>
#include <vector>

namespace gi::voxel {

bool ConeTracePass::init(gl::ShaderLibrary& shaders, std::string& error) {
    if (!mPrograms.init(shaders, {"voxel/cone_trace",
                {{GL_VERTEX_SHADER, "voxel/cone_trace.vert"},
                 {GL_FRAGMENT_SHADER, "voxel/cone_trace.frag"}}, {}}, error)) {
        return false;
    }
    mDepthProgram = shaders.build({"voxel/cone_trace_depth",
            {{GL_VERTEX_SHADER, "voxel/cone_trace.vert"},
             {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    return bool(mDepthProgram);
}

// Draws into mTarget and mSpecular at once, mSpecular cleared to 0.
void ConeTracePass::bindSpecularTarget() {
    if (mSpecularSize != mSize || !mSpecular) {
        mSpecular = gl::createTargetTexture({GL_RGBA16F, "voxel/indirect_specular", true}, mSize);
        std::string error;
        if (!gl::attachFramebuffer(mSpecularFramebuffer, "voxel/trace_specular",
                    {&mTarget.color(), &mSpecular}, &mTarget.depth(), error)) {
            std::fprintf(stderr, "%s\n", error.c_str());
        }
        mSpecularSize = mSize;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mSpecularFramebuffer.id());
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(mSpecularFramebuffer.id(), GL_COLOR, 1, zero);
}

void ConeTracePass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    const int stride = out.pattern.stride;
    mTarget.resize((out.size + stride - 1) / stride);
    mSize = mTarget.size();
    gl::GpuScope scope(profiler, "voxel/trace");
    mTarget.bind();
    mTarget.clear();
    if (in.specular) bindSpecularTarget();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, in.frameUniforms.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
    const VoxelTextures& voxels = in.textures;
    // Built per cascade shape and per use of the specular cone: llvmpipe runs the glossy
    // branch's shading for every pixel of a group whenever the branch exists.
    std::vector<std::string> defines =
            VoxelShape{voxels.resolution, voxels.levels, voxels.anisotropic}.defines();
    defines.push_back(std::string("CONE_TRACE_SPECULAR ") + (in.specular ? "1" : "0"));
    const GLuint program = mPrograms.id(defines);
    // Pixel x of the strided image stands for pixel stride x + phase of the whole trace:
    // shifting NDC by (1 - (2 phase + 1) / stride) / size puts its centre on that pixel's.
    const glm::vec2 offset =
            (1.0f - (2.0f * glm::vec2(out.pattern.phase) + 1.0f) / float(stride)) /
            glm::vec2(mSize);
    for (GLuint p : {program, mDepthProgram.id()}) {
        glProgramUniform2f(p, LOC_CONE_TRACE_OFFSET, offset.x, offset.y);
    }
    // Depth first, so that only the visible surface of each pixel traces its cones: without
    // it every surface drawn before the one in front traced its cones for nothing.
    in.scene.drawDepthPrepass(mDepthProgram.id());
    glUseProgram(program);
    glProgramUniform3i(program, LOC_CONE_TRACE_PATTERN, stride, out.pattern.phase.x,
            out.pattern.phase.y);
    glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, in.textures.albedo.id());
    glBindTextureUnit(BIND_TEX_VOXEL_IRRADIANCE, in.textures.irradiance.id());
    glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, in.textures.normal.id());
    glBindTextureUnit(BIND_TEX_VOXEL_PYRAMID, in.textures.pyramid.id());
    if (in.textures.anisotropic) {
        glBindTextureUnit(BIND_TEX_VOXEL_DIRECTIONAL, in.textures.directional.id());
    }
    in.scene.drawAll(program, true);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace gi::voxel
