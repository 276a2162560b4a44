// C++ view of shaders/common/shared.h: the GLSL vector types are glm's, and the layouts are
// checked here so a struct edited on one side fails the build instead of the picture.
#pragma once

#include <glm/glm.hpp>

namespace gi::shader {
using glm::ivec4;
using glm::mat4;
using glm::vec4;
} // namespace gi::shader

#include "common/shared.h"

static_assert(sizeof(gi::shader::FrameUniforms) == 288, "FrameUniforms std140 layout drifted");
static_assert(sizeof(gi::shader::GpuLight) == 64, "GpuLight std430 layout drifted");
static_assert(sizeof(gi::shader::GpuEmitter) == 64, "GpuEmitter std430 layout drifted");
static_assert(sizeof(gi::shader::GpuMaterial) == 64, "GpuMaterial std430 layout drifted");
static_assert(sizeof(gi::shader::GpuShadow) == 96, "GpuShadow std430 layout drifted");
static_assert(sizeof(gi::shader::VoxelUniforms) == 8 * 16 + 16 * 10,
        "VoxelUniforms std140 layout drifted");
static_assert(sizeof(gi::shader::AtlasUniforms) == 6 * 16, "AtlasUniforms std140 layout drifted");
static_assert(sizeof(gi::shader::GpuVpl) == 3 * 16, "GpuVpl std430 layout drifted");
static_assert(sizeof(gi::shader::VplUniforms) == 3 * 16, "VplUniforms std140 layout drifted");
static_assert(sizeof(gi::shader::SvoUniforms) == 3 * 16, "SvoUniforms std140 layout drifted");
static_assert(sizeof(gi::shader::SvoBuildState) == 2 * 16 + 4 * (SVO_MAX_DEPTH + 2),
        "SvoBuildState std430 layout drifted");
