// Atlas resolve (thesis 4.7): the atlas geometry drawn from the camera at the output size;
// each pixel looks the lit atlas up bilinearly at its surface's atlas coordinate. This turns
// the atlas' E_ind into the screen-space texture of the GiOutputs contract.
// Inputs : GpuScene (draws, materials for alpha-masked cut-outs), AtlasGeometry, frame UBO
//          (camera), AtlasTextures lit.
// Outputs: indirect(), RGBA16F at the output size: rgb = E_ind (W/m^2) of the surface in the pixel,
//          a = its view depth (m); 0 where no surface.
#pragma once

#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::atlas {

class AtlasResolvePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // draws, materials (alpha-masked cut-outs)
        const AtlasGeometry& geometry;     // world positions and atlas coordinates
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140: the camera
        const gl::Buffer& atlasUniforms;   // AtlasUniforms, std140
        const AtlasTextures& textures;     // lit (RGBA16F, E_ind in W/m^2), sampled bilinearly
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of indirect(); reallocated when it changes
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

    const gl::Texture& indirect() const { return mTarget.color(); }
    glm::ivec2 size() const { return mSize; }

private:
    gl::ProgramRef mProgram;
    gl::RenderTarget mTarget{"atlas/resolve", {GL_RGBA16F, "atlas/indirect", true},
            {GL_DEPTH_COMPONENT32F, "atlas/resolve_depth"}};
    glm::ivec2 mSize{0};
};

} // namespace gi::atlas
