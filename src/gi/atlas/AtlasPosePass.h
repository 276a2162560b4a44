// Keeps the atlas' vertices in the pose of the scene's animated instances (atlas/follow_pose):
// each atlas vertex copies the world position and normal of the GpuScene vertex it was split
// from. Run whenever GpuScene::geometryVersion() changes; the atlas coordinates stay.
// Inputs : GpuScene's vertex buffer (posed by updateDynamic), AtlasGeometry's sources.
// Outputs: AtlasGeometry's vertex buffer (positions and normals rewritten in place).
#pragma once

#include "gi/atlas/AtlasGeometry.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"

namespace gi::atlas {

class AtlasPosePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;      // vertex buffer in the current pose (world space)
    };
    struct Outputs {
        const AtlasGeometry& geometry;     // vertex buffer: positions (m), normals rewritten
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram;
};

} // namespace gi::atlas
