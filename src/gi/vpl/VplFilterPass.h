// Merges the interleaved VPL subsets (shaders/vpl/interleave_filter.comp): each pixel averages
// the 4x4 window holding every subset once, over neighbours on the same surface. Without
// interleaving it copies the gather.
// Inputs : the gather's result, the G-buffer's normals, VplUniforms.
// Outputs: result(), RGBA16F: rgb = E_ind (W/m^2), a = view depth (m), the technique's output.
#pragma once

#include "gi/vpl/VplGBufferPass.h"

namespace gi::vpl {

class VplFilterPass {
public:
    struct Inputs {
        const gl::Texture& gathered;
        const VplGBufferPass& gBuffer;
        const gl::Buffer& uniforms;   // VplUniforms
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, gl::GpuProfiler& profiler);
    const gl::Texture& result() const { return mResult; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mResult;
    glm::ivec2 mSize{0};
};

} // namespace gi::vpl
