// Final shading at full resolution: direct light from every light (DESIGN.md conventions) with
// the material model of material.model (Lambertian + Blinn-Phong, or glTF metallic-
// roughness), emission and the GI technique's indirect light, into a
// linear-radiance target. An optional depth pre-pass (render.depth_prepass) lets each pixel
// be shaded once however much geometry overlaps it.
// Inputs : the GpuScene (vertices, materials, lights), shadow maps, the frame UBO, the GI
//          technique's screen-space indirect irradiance (GiOutputs), if any.
// Outputs: colour RGBA32F, linear radiance W/(m^2 sr), alpha = 1 on geometry, 0 elsewhere;
//          depth DEPTH_COMPONENT32F.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/ProgramVariants.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "render/FrameSwitches.h"
#include "render/ShadowPass.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

namespace gi::render {

class ForwardPass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // world-space vertices, materials, lights
        const ShadowPass& shadows;         // maps and GpuShadow table, already rendered
        const gl::Buffer& frameUniforms;   // FrameUniforms, std140
        // RGBA16F, rgb = E_ind (W/m^2), a = view depth (m), at indirectSize texels (may be
        // smaller than the target); nullptr: direct light only
        const gl::Texture* indirect;
        glm::ivec2 indirectSize;
        bool depthPrepass;                 // render.depth_prepass
        // RGBA16F at indirectSize: rgb = indirect specular radiance (W/(m^2 sr)), a = view
        // depth (m); nullptr: none (only voxel GI with material.model=gltf makes it)
        const gl::Texture* indirectSpecular = nullptr;
        FrameSwitches switches{};          // the program is compiled for these
    };
    struct Outputs {
        const gl::RenderTarget& target;    // RGBA32F colour + DEPTH_COMPONENT32F, cleared here
    };

    // Returns false with the shader error if the program does not build.
    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramVariants mPrograms;     // per FrameSwitches
    gl::ProgramRef mDepthProgram;
};

} // namespace gi::render
