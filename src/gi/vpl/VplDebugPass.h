// The VPL debug views (--output vpl-points, vpl-subset, vpl-visibility; the viewer's output
// cycle): the VPLs the camera sees as discs coloured by their flux over the grey surfaces,
// the same with one pixel class's subset highlighted (the VPLs every pixel (x, y) with
// (x mod 4) + 4 (y mod 4) = vpl.debug_subset gathers from), and the visibility term, the
// mean visibility of the VPLs facing each surface (shaders/vpl/debug_splat.comp,
// debug_compose.comp).
// Inputs : the G-buffer, the VPLs, VplUniforms, FrameUniforms, the filter's output (for the
//          visibility view: the gather run with VPL_GATHER_VISIBLE_FRACTION).
// Outputs: image(), RGBA32F at the G-buffer's size, alpha = coverage.
#pragma once

#include "gi/vpl/VplGBufferPass.h"

namespace gi::vpl {

class VplDebugPass {
public:
    struct Inputs {
        const VplGBufferPass& gBuffer;
        const gl::Buffer& vpls;            // GpuVpl[]
        int vplCount;
        const gl::Buffer& uniforms;        // VplUniforms
        const gl::Buffer& frameUniforms;   // FrameUniforms of the camera view
        const gl::Texture& merged;         // the filter's result
        int highlightClass;                // vpl.debug_subset
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // view: VPL_DEBUG_*.
    void execute(int view, const Inputs& in, gl::GpuProfiler& profiler);
    const gl::Texture& image() const { return mImage; }

private:
    gl::ProgramRef mSplat;
    gl::ProgramRef mCompose;
    gl::Texture mIds;     // r32ui, the VPL key splatted over each pixel
    gl::Texture mImage;
    glm::ivec2 mSize{0};
};

} // namespace gi::vpl
