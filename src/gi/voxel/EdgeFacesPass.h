// Finds the two faces of every edge voxel in the occupancy's level 0 (shaders/voxel/
// edge_faces.comp, common/voxel_edge_faces.glsl): the visibility marches then block what enters
// the solid between them instead of what crosses the edge's mean plane, which cuts the edge
// off and blocked segments grazing a face beside it. Once per voxelization of the occupancy.
// Inputs : VoxelTextures normal, level 0 (voxelized), VoxelUniforms.
// Outputs: VoxelTextures edgeFaces (every texel written; zero where a voxel is no edge or its
//          faces were not found).
#pragma once

#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::voxel {

class EdgeFacesPass {
public:
    struct Inputs {
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: resolution
    };
    struct Outputs {
        const VoxelTextures& textures;     // normal read, edgeFaces written
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::voxel
