// A fragment program run once per atlas texel (a full-screen triangle over the atlas):
// what the dilation and the further bounces' senders share. The caller binds the program's
// inputs; draw() binds the framebuffer, the atlas viewport and plain state around the draw.
#pragma once

#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <string>

namespace gi::atlas {

class AtlasTexelPass {
public:
    // Builds `fragmentShader` (under shaders/) with the full-screen vertex shader as `name`.
    bool init(gl::ShaderLibrary& shaders, const char* name, const char* fragmentShader,
            std::string& error);
    void draw(const gl::Framebuffer& framebuffer, int resolution) const;

private:
    gl::ProgramRef mProgram;
    gl::VertexArray mEmpty;
};

} // namespace gi::atlas
