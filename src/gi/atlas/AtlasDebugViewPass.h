// Atlas debug views (--output atlas-direct, -normal, -position, -albedo, -indirect,
// -charts): one atlas layer mapped onto the scene from the camera (shaders/atlas/
// debug_view.frag says what each shows).
// Inputs : GpuScene, AtlasGeometry, frame UBO, AtlasUniforms (size.w = ATLAS_VIEW_*),
//          AtlasTextures.
// Outputs: RGBA32F at the output size, linear values, alpha = 1 where a surface was drawn.
#pragma once

#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::atlas {

class AtlasDebugViewPass {
public:
    struct Inputs {
        const scene::GpuScene& scene;
        const AtlasGeometry& geometry;
        const gl::Buffer& frameUniforms;
        const gl::Buffer& atlasUniforms;
        const AtlasTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, glm::ivec2 size, gl::GpuProfiler& profiler);
    const gl::Texture& image() const { return mImage; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mImage, mDepth;
    gl::Framebuffer mFramebuffer;
    glm::ivec2 mSize{0};
};

} // namespace gi::atlas
