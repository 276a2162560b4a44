// Geometry-shader voxelization (thesis 4.2.2, 4.3.3.1): every triangle is projected along
// its dominant axis onto a v x multiplier raster spanning the coarsest level; each fragment
// averages its albedo and normal into the finest level containing it, under the voxel's
// spinlock. Depth test, culling and colour writes are off.
// Inputs : GpuScene (world-space triangles, materials), VoxelUniforms (cascade placement).
// Outputs: VoxelTextures albedo (rgb albedo, a = 1 where occupied) and normal, lock counts;
//          anisotropic: directional a = surface area per face (directional_build.comp).
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

namespace gi::voxel {

class VoxelizePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // world-space triangles (m), materials
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: placement, raster area
        int rasterSize;                    // pixels per side: v x voxel.multiplier
        int samples;                       // per pixel (voxel.msaa)
        scene::GpuScene::DrawSet draws = scene::GpuScene::DrawSet::All;   // which instances
    };
    struct Outputs {
        // albedo (rgba16f), normal (rgba8_snorm), irradiance.a (surface area in voxel face
        // areas) and lock (r32ui) of every level, added to; cleared or restored by the caller
        const VoxelTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
    gl::Framebuffer mFramebuffer;   // no attachments: rasterization only
    int mSize = 0;
    int mSamples = 0;
};

} // namespace gi::voxel
