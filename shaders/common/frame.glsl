// Per-view uniforms (layout in shared.h).
#ifndef GI_FRAME_GLSL
#define GI_FRAME_GLSL

#include "shared.h"

layout(std140, binding = BIND_UBO_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};

// The frame's switches. A program built for one setting of them (FRAME_SHADING_MODEL,
// FRAME_SHADOW_METHOD, FRAME_SHADOWS, FRAME_SHADOW_MAPS; gl/ProgramVariants.h) reads them as
// constants and the compiler drops the paths it never takes; without them they come from the
// frame uniforms (the kinds of shadow map: all present).
int shadingModel() {
#ifdef FRAME_SHADING_MODEL
    return FRAME_SHADING_MODEL;
#else
    return int(frame.shading.z);
#endif
}

int shadowMethod() {
#ifdef FRAME_SHADOW_METHOD
    return FRAME_SHADOW_METHOD;
#else
    return int(frame.shadowing.x);
#endif
}

// Whether some light has a shadow map of `kind` (SHADOW_2D, SHADOW_CUBE). llvmpipe runs every
// branch of a shader for all pixels of a group whenever one of them takes it, so a filter no
// light needs costs as much as one that runs (results-performance.md).
bool shadowMapsOfKind(int kind) {
#ifdef FRAME_SHADOW_MAPS
    return (FRAME_SHADOW_MAPS & (1 << kind)) != 0;
#else
    return true;
#endif
}

bool shadowsApplied() {
#ifdef FRAME_SHADOWS
    return FRAME_SHADOWS != 0;
#else
    return frame.shading.w != 0.0;
#endif
}

#endif
