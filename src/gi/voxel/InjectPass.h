// Light injection (thesis 4.2.3, 4.3.3.2, Alg. 3): the scene is rendered from every light
// (directional: orthographic over the coarsest level; spot: perspective over its outer
// cone; point: six 90-degree views) at voxel.inject_resolution; each visible fragment
// averages its Lambert irradiance into its voxel. A depth pre-pass per view makes the
// forced early depth test exact. After each light a compute pass adds the light's mean to
// the per-voxel sum over lights (the "finalize" step) and the lock counts are cleared.
// Inputs : GpuScene (geometry, lights), VoxelUniforms, the light views (injectionViews).
// Outputs: VoxelTextures irradiance (rgb = E summed over lights, W/m^2; a = light count);
//          anisotropic: directional rgb = flux per face (directional_build.comp).
#pragma once

#include "gi/voxel/CascadeVolume.h"
#include "gi/voxel/VoxelTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"
#include "scene/LightViews.h"
#include "scene/Scene.h"

#include <vector>

namespace gi::voxel {

// The views a light is injected through (exposed for tests).
using LightView = scene::LightView;

// Views covering the scene inside the coarsest level, `resolution` pixels per side.
[[nodiscard]] std::vector<LightView> injectionViews(const std::vector<scene::Light>& lights,
        const CascadeVolume& volume, const scene::Aabb& sceneBounds, int resolution);

// Fixed-point units per unit of flux / voxel face area for the sums of INJECT_AREA
// (voxel_flux_sum.glsl): the largest power of two at which no voxel's sum can pass 2^31,
// even if every pixel of every view (`resolution` per side) carried its light's strongest
// flux (lightStrength x footprint, 8 times over for the glTF BRDF's reflectance at an angle)
// into one voxel of the finest level (edge `finestVoxel`, m), the lights scaled by the GPU's
// pre-exposure (GpuScene::exposure). Resolution is thus relative to the lights' whole flux,
// whatever their units; 1 when no view carries flux.
[[nodiscard]] double fluxSumScale(const std::vector<scene::Light>& lights,
        const std::vector<LightView>& views, int resolution, float finestVoxel, float exposure);

class InjectPass {
public:
    struct Inputs {
        const scene::GpuScene& scene;             // world-space triangles, materials, lights
        const std::vector<LightView>& views;      // grouped by light, in light order
        const gl::Buffer& voxelUniforms;          // VoxelUniforms, std140: placement, modes
        int resolution;                           // light-view pixels per side
        bool fragmentMean;                        // INJECT_FRAGMENT: finalize after each light
        double fluxScale;                         // INJECT_AREA: fluxSumScale
    };
    struct Outputs {
        // irradiance (rgba16f, W/m^2 x coverage, summed over lights); helper, flux sums and
        // lock are scratch, albedo is read for the coverage
        const VoxelTextures& textures;
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    // Sets light view number `ordinal`'s matrix, axis, footprint and light on both programs.
    void setView(const LightView& view, std::size_t ordinal, double fluxScale) const;
    void finalize(const Inputs& in, const VoxelTextures& textures, gl::GpuProfiler& profiler);

    gl::ProgramRef mDepthProgram, mInjectProgram, mFinalizeProgram;
    gl::RenderTarget mTarget{"voxel/inject", {}, {GL_DEPTH_COMPONENT32F, "voxel/inject_depth"}};
};

} // namespace gi::voxel
