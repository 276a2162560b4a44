// Edge-aware smoothing of the cone-traced indirect irradiance at trace resolution (see
// shaders/voxel/indirect_filter.comp): a box filter of radius voxel.filter texels (at
// voxel.trace_scale 0.5, scaled with the trace scale so it covers the same part of the image),
// each neighbour weighted by its view depth and its distance from the centre's plane, that,
// with the per-pixel cone jitter, averages 16 cone rings per pixel.
// Inputs : ConeTracePass output (RGBA16F, rgb = E_ind W/m^2, a = view depth m), VoxelUniforms.
// Outputs: result(), RGBA16F texture of the same size and meaning.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ProgramVariants.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

namespace gi::voxel {

class IndirectFilterPass {
public:
    struct Inputs {
        const gl::Texture& source;         // RGBA16F, rgb = E_ind (W/m^2), a = view depth (m)
        const gl::Buffer& voxelUniforms;   // VoxelUniforms, std140: smoothing.x = radius
        int radius = 1;                    // texels, 1..VOXEL_FILTER_MAX_RADIUS (= smoothing.x)
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of source and of result()
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);
    const gl::Texture& result() const { return mResult; }

private:
    gl::ProgramVariants mPrograms;   // per radius (FILTER_RADIUS)
    gl::Texture mResult;
    glm::ivec2 mSize{0};
};

} // namespace gi::voxel
