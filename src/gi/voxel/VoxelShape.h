// The cascade shape a voxel shader can be compiled for: a shader that includes
// shaders/common/voxel_cascade.glsl reads the resolution, the level count and (the cone
// trace) the voxel kind from the voxel uniforms; built with these defines
// (gl/ProgramVariants.h) it reads them as constants, and the loops over levels fold and the
// finer-level and anisotropic paths a shape never takes drop out.
#pragma once

#include <string>
#include <vector>

namespace gi::voxel {

struct VoxelShape {
    int resolution = 0;
    int levels = 0;
    bool anisotropic = false;

    // VOXEL_SHAPE_RESOLUTION, VOXEL_SHAPE_LEVELS, VOXEL_SHAPE_ANISOTROPIC.
    [[nodiscard]] std::vector<std::string> defines() const;
};

} // namespace gi::voxel
