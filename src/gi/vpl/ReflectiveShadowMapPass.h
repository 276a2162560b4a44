// Reflective shadow maps (SEEDS.md section 4): draws the scene through every light's views
// (scene/LightViews.h) and reads back, per view, the lit pixels (position, normal, reflected
// flux; shaders/vpl/rsm.frag). Runs only when the VPLs are drawn anew (lights or geometry
// changed), so the readback stalls no steady frame.
// Inputs : GpuScene (geometry, materials, lights), the views, their resolution.
// Outputs: the lit texels on the CPU.
#pragma once

#include "gi/vpl/RsmTexel.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"
#include "scene/LightViews.h"

#include <string>
#include <vector>

namespace gi::vpl {

class ReflectiveShadowMapPass {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // The lit texels of every view, in view order; gltfReflectance: the flux a texel sends on
    // is what the glTF BRDF reflects (material.model=gltf), else the base colour's share.
    [[nodiscard]] std::vector<RsmTexel> execute(const scene::GpuScene& scene,
            const std::vector<scene::LightView>& views, int resolution, bool gltfReflectance,
            gl::GpuProfiler& profiler);

private:
    bool allocate(int resolution);
    void drawView(const scene::GpuScene& scene, const scene::LightView& view) const;
    void readBack(int light, std::vector<RsmTexel>& texels) const;

    gl::ProgramRef mDepthProgram;
    gl::ProgramRef mProgram;
    int mResolution = 0;
    gl::Texture mPosition, mNormal, mFlux, mDepth;
    gl::Framebuffer mFramebuffer;
};

} // namespace gi::vpl
