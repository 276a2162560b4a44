// The end of the VPL passes that compute one pixel per invocation: the target bound as the
// image they write (or read and write), VPL_LOCAL_SIZE^2 groups over `size`, and a barrier for a consumer that
// samples the target as a texture (the next pass, or the forward pass).
#pragma once

#include "gl/Objects.h"
#include "gl/Shared.h"

#include <glm/glm.hpp>

namespace gi::vpl {

inline void dispatchOverPixels(const gl::Texture& target, glm::ivec2 size,
        GLenum access = GL_WRITE_ONLY, GLenum format = GL_RGBA16F) {
    glBindImageTexture(BIND_IMG_VPL_TARGET, target.id(), 0, GL_FALSE, 0, access, format);
    const glm::ivec2 groups = (size + VPL_LOCAL_SIZE - 1) / VPL_LOCAL_SIZE;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::vpl
