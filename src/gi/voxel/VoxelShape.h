// Programs compiled for one cascade shape. A voxel shader that includes
// shaders/common/voxel_cascade.glsl reads the resolution, the level count and (the cone
// trace) the voxel kind from the voxel uniforms; built with this shape's defines it reads
// them as constants instead, so the compiler folds the loops over levels and drops the
// finer-level and anisotropic paths a shape never takes. On llvmpipe this is worth more than
// on a GPU: both sides of every branch run with lanes masked off, so an untaken path costs as
// much as a taken one (the Cornell box's cone trace, one isotropic level: x0.68 of the
// runtime-switched shader, docs/results-performance.md).
#pragma once

#include "gl/ShaderLibrary.h"

#include <compare>
#include <map>
#include <string>
#include <vector>

namespace gi::voxel {

struct VoxelShape {
    int resolution = 0;
    int levels = 0;
    bool anisotropic = false;

    auto operator<=>(const VoxelShape&) const = default;
    // VOXEL_SHAPE_RESOLUTION, VOXEL_SHAPE_LEVELS, VOXEL_SHAPE_ANISOTROPIC.
    [[nodiscard]] std::vector<std::string> defines() const;
};

// One program description built once per shape, on first use.
class ShapedPrograms {
public:
    // Builds the shape-free program (every value read at run time), which also checks the
    // sources compile.
    [[nodiscard]] bool init(gl::ShaderLibrary& shaders, gl::ProgramDesc desc, std::string& error);

    // The program for `shape`. A shape whose build fails (the shape-free program compiled,
    // so only a driver limit could) reports it once on stderr and runs the shape-free one.
    [[nodiscard]] GLuint id(const VoxelShape& shape);

private:
    gl::ShaderLibrary* mShaders = nullptr;
    gl::ProgramDesc mDesc;
    gl::ProgramRef mGeneric;
    std::map<VoxelShape, gl::ProgramRef> mShaped;
};

} // namespace gi::voxel
