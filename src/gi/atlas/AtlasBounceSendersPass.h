// What the atlas' texels send to a further bounce's gather (gi.bounces > 1;
// shaders/atlas/bounce_senders.frag): direct radiance plus rho/pi x the E_ind of the bounce
// just gathered and dilated, per side.
// Inputs : AtlasTextures direct, directBack, albedo, lit and litBack (the last bounce's
//          E_ind); AtlasUniforms (whether there are back sides).
// Outputs: AtlasTextures senders and sendersBack.
#pragma once

#include "gi/atlas/AtlasTexelPass.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

namespace gi::atlas {

class AtlasBounceSendersPass {
public:
    struct Inputs {
        const AtlasTextures& textures;     // direct, albedo, lit (and their back layers)
        const gl::Buffer& atlasUniforms;   // AtlasUniforms, std140: back sides or not
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Draws into textures.senders from now on; false with a message if that is not renderable.
    bool attach(const AtlasTextures& textures, std::string& error);
    void execute(const Inputs& in, gl::GpuProfiler& profiler);

private:
    AtlasTexelPass mPass;
    gl::Framebuffer mFramebuffer;
    int mResolution = 0;
};

} // namespace gi::atlas
