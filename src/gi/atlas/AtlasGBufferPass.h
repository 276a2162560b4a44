// Atlas G-buffer (thesis 4.4): the scene drawn with every vertex at its atlas coordinate into
// one framebuffer with four targets — direct radiance (Lambert, shadowed, every light), normal,
// world position with the texel's sample area, albedo; alpha 0 = no surface. Three draws: an
// exact one (texel centres inside a triangle), a conservative one (geometry shader,
// gbuffer.geom) that fills every further texel a triangle touches, so bilinear lookups inside
// a chart never read an empty texel (a depth buffer keeps the exact draw's texels), and a
// conservative one that adds each triangle's world area inside each texel to position.w: the
// texel's sample area for the gather, so the texels' areas add up to the surface area even
// where charts or triangles are smaller than a texel.
// Inputs : GpuScene (draws, materials, lights), AtlasGeometry, ShadowMaps (already
//          rendered), frame UBO (light count, shadows on/off), AtlasUniforms (resolution).
// Outputs: AtlasTextures direct, normal, position, albedo.
#pragma once

#include "gi/ShadowMaps.h"
#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

namespace gi::atlas {

class AtlasGBufferPass {
public:
    struct Inputs {
        const scene::GpuScene& scene;    // draws, materials, lights
        const AtlasGeometry& geometry;   // world positions (m) and atlas coordinates
        const ShadowMaps& shadows;       // maps of every light, already rendered
        const gl::Buffer& frameUniforms; // FrameUniforms, std140: light count, shadows on/off
        const gl::Buffer& atlasUniforms; // AtlasUniforms, std140: resolution
    };
    struct Outputs {
        const AtlasTextures& textures;   // direct, normal, position, albedo (attach() bound)
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Attaches the layers; false with a message if the framebuffer is incomplete.
    bool attach(const AtlasTextures& textures, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mExact, mConservative, mArea;
    gl::Framebuffer mFramebuffer;
    gl::Texture mDepth;
    int mResolution = 0;
};

} // namespace gi::atlas
