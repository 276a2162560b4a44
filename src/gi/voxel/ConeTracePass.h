// Cone tracing into its own framebuffer at voxel.trace_scale of the output per axis (thesis
// 4.2.5, 4.3.3.4): the scene is rasterised at that resolution and each fragment traces 9
// cones through the cascade, writing indirect irradiance E_ind (W/m^2).
// Inputs : GpuScene, frame UBO (camera), VoxelUniforms, VoxelTextures (sampled, filtered).
// Outputs: RGBA16F target: rgb = E_ind, a = view depth (m); cleared to 0 where no surface.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::voxel {

class ConeTracePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;
        const gl::Buffer& frameUniforms;
        const gl::Buffer& voxelUniforms;
        const VoxelTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void resize(glm::ivec2 size);
    void execute(const Inputs& in, gl::GpuProfiler& profiler);

    const gl::Texture& indirect() const { return mIndirect; }
    glm::ivec2 size() const { return mSize; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mIndirect, mDepth;
    gl::Framebuffer mFramebuffer;
    glm::ivec2 mSize{0};
};

} // namespace gi::voxel
