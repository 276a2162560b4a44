// Debug views of the cascade (voxel albedo, irradiance, normal of one level) as seen from the
// camera: a full-screen ray-march that shows the first occupied voxel along each pixel's ray.
// Inputs : frame UBO (inverse view-projection, output size), VoxelUniforms (grid.z = level,
//          injection.w = view), VoxelTextures.
// Outputs: RGBA32F image at the output size, linear values, alpha = 1 where a voxel was hit.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

namespace gi::voxel {

class VoxelDebugViewPass {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const gl::Buffer& frameUniforms, const gl::Buffer& voxelUniforms,
            const VoxelTextures& textures, glm::ivec2 size, gl::GpuProfiler& profiler);
    const gl::Texture& image() const { return mImage; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mImage;
    gl::Framebuffer mFramebuffer;
    gl::VertexArray mEmpty;
    glm::ivec2 mSize{0};
};

} // namespace gi::voxel
