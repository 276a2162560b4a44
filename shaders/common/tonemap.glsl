// The display's tone curves, the GLSL twin of core/ToneMap.cpp: both read their constants
// from shared.h, so the viewer and `voxatlas render` map radiance the same way.
#ifndef GI_TONEMAP_GLSL
#define GI_TONEMAP_GLSL

#include "shared.h"

vec3 filmicCurve(vec3 x) {
    x = max(x, vec3(0.0));
    return clamp(x * (TONE_ACES_A * x + TONE_ACES_B) /
                 (x * (TONE_ACES_C * x + TONE_ACES_D) + TONE_ACES_E), 0.0, 1.0);
}

// Exposed linear radiance to display-referred values in [0, 1].
vec3 toneCurve(vec3 exposed, int curve) {
    return curve == TONE_CURVE_FILMIC ? filmicCurve(exposed) : clamp(exposed, 0.0, 1.0);
}

#endif
