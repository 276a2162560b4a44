// What the VPL gather and its filter share: the uniforms and the G-buffer.
#ifndef GI_VPL_COMMON_GLSL
#define GI_VPL_COMMON_GLSL

#include "../common/shared.h"

layout(std140, binding = BIND_UBO_VPL) uniform VplBlock {
    VplUniforms vpl;
};

layout(binding = BIND_TEX_VPL_POSITION) uniform sampler2D gPosition;
layout(binding = BIND_TEX_VPL_NORMAL) uniform sampler2D gNormal;

#endif
