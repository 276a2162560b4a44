// Atlas resolve (thesis 4.7): the atlas geometry drawn from the camera at the output size;
// each pixel looks the lit atlas up bilinearly at its surface's atlas coordinate. This turns
// the atlas' E_ind into the screen-space texture of the GiOutputs contract.
// Inputs : GpuScene (draws, materials for alpha-masked cut-outs), AtlasGeometry, frame UBO
//          (camera), AtlasTextures lit.
// Outputs: RGBA16F at the output size: rgb = E_ind (W/m^2) of the surface in the pixel,
//          a = its view depth (m); 0 where no surface.
#pragma once

#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::atlas {

class AtlasResolvePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;
        const AtlasGeometry& geometry;
        const gl::Buffer& frameUniforms;
        const gl::Buffer& atlasUniforms;
        const AtlasTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void resize(glm::ivec2 size);
    void execute(const Inputs& in, gl::GpuProfiler& profiler);

    const gl::Texture& indirect() const { return mIndirect; }
    glm::ivec2 size() const { return mSize; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mIndirect, mDepth;
    gl::Framebuffer mFramebuffer;
    glm::ivec2 mSize{0};
};

} // namespace gi::atlas
