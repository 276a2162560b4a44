// Atlas debug views (--output atlas-direct, -normal, -position, -albedo, -indirect,
// -charts): one atlas layer mapped onto the scene from the camera (shaders/atlas/
// debug_view.frag says what each shows).
// Inputs : GpuScene, AtlasGeometry, frame UBO, AtlasUniforms (size.w = ATLAS_VIEW_*),
//          AtlasTextures.
// Outputs: image(), RGBA32F at the output size, linear values, alpha = 1 where a surface was drawn.
#pragma once

#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::atlas {

class AtlasDebugViewPass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // draws, materials
        const AtlasGeometry& geometry;     // world positions and atlas coordinates
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140: the camera
        const gl::Buffer& atlasUniforms;   // AtlasUniforms, std140: size.w = ATLAS_VIEW_*
        const AtlasTextures& textures;     // every layer, sampled
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of image(); reallocated when it changes
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);
    const gl::Texture& image() const { return mTarget.color(); }

private:
    gl::ProgramRef mProgram;
    gl::RenderTarget mTarget{"atlas/debug_view", {GL_RGBA32F, "atlas/debug_view"},
            {GL_DEPTH_COMPONENT32F, "atlas/debug_view_depth"}};
};

} // namespace gi::atlas
