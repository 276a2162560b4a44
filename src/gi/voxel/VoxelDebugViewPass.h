// Debug views of the cascade (voxel albedo, irradiance, normal of one level) as seen from the
// camera: a full-screen ray-march that shows the first occupied voxel along each pixel's ray.
// Inputs : frame UBO (inverse view-projection, output size), VoxelUniforms, VoxelTextures,
//          the level and the view shown.
// Outputs: image(), RGBA32F at Outputs::size, linear values, alpha = 1 where a voxel was hit.
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

namespace gi::voxel {

class VoxelDebugViewPass {
public:
    enum class View { Albedo = 0, Irradiance = 1, Normal = 2 };   // VIEW_* of debug_view.frag
    struct Inputs {
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140: the camera
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement
        const VoxelTextures& textures;     // albedo, irradiance, normal (sampled)
        int level;                         // cascade level shown, 0 = finest
        View view;
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of image(); reallocated when it changes
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);
    const gl::Texture& image() const { return mTarget.color(); }

private:
    gl::ProgramRef mProgram;
    gl::RenderTarget mTarget{"voxel/debug_view", {GL_RGBA32F, "voxel/debug_view"}};
    gl::VertexArray mEmpty;
};

} // namespace gi::voxel
