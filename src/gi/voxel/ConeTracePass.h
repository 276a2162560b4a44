// Cone tracing into its own framebuffer at voxel.trace_scale of the output per axis (thesis
// 4.2.5, 4.3.3.4): the scene is rasterised at that resolution and each fragment traces 9
// cones through the cascade, writing indirect irradiance E_ind (W/m^2). A depth pre-pass
// leaves the tracing to the visible surface of each pixel. With glossy materials
// (material.model=gltf) each fragment also traces one specular cone (cone_trace.frag).
// Inputs : GpuScene, frame UBO (camera), VoxelUniforms, VoxelTextures (sampled, filtered).
// Outputs: indirect(), RGBA16F at Outputs::size / stride: rgb = E_ind, a = view depth (m);
//          cleared to 0 where no surface. A stride of 2 traces one pixel of each 2x2 block
//          (TraceReusePass.h fills in the others).
//          specular() (Inputs::specular only), RGBA16F of the same size: rgb = indirect
//          specular radiance towards the camera (W/(m^2 sr)), a = view depth.
#pragma once

#include "gi/voxel/VoxelShape.h"
#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ProgramVariants.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::voxel {

class ConeTracePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // world-space triangles, materials
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140: the camera
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement, cone set-up
        const VoxelTextures& textures;     // albedo, irradiance, normal, pyramid (and
                                           // directional, anisotropic); propagated
        bool specular = false;             // also trace the specular cone into specular()
    };
    // Which pixels of the trace this pass covers: pixel (stride x + phase.x, stride y +
    // phase.y) of an image of Outputs::size, as pixel (x, y) of indirect().
    struct Pattern {
        int stride = 1;
        glm::ivec2 phase{0};
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of the whole trace (a multiple of the
                                           // stride); indirect() is this / stride
        Pattern pattern{};
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

    const gl::Texture& indirect() const { return mTarget.color(); }
    const gl::Texture& specular() const { return mSpecular; }
    glm::ivec2 size() const { return mSize; }

private:
    void bindSpecularTarget();

    gl::ProgramVariants mPrograms;     // the trace, built per cascade shape (VoxelShape.h)
    gl::ProgramRef mDepthProgram;      // the depth pre-pass
    gl::RenderTarget mTarget{"voxel/trace", {GL_RGBA16F, "voxel/indirect", true},
            {GL_DEPTH_COMPONENT32F, "voxel/trace_depth"}};
    glm::ivec2 mSize{0};
    // The specular cone's target, and a framebuffer drawing into mTarget's colour and depth
    // and it; made again whenever mTarget is reallocated.
    gl::Texture mSpecular;
    gl::Framebuffer mSpecularFramebuffer;
    glm::ivec2 mSpecularSize{0};
};

} // namespace gi::voxel
