// Per-view uniforms (layout in shared.h).
#ifndef GI_FRAME_GLSL
#define GI_FRAME_GLSL

#include "shared.h"

layout(std140, binding = BIND_UBO_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};

#endif
