// Present pass, fragment stage: linear radiance to the display the way core/ToneMap.h maps
// PNG outputs: times the exposure, through the tone curve (or a clamp to [0, 1]), sRGB
// encoded (IEC 61966-2-1). The encode is done here because GL_FRAMEBUFFER_SRGB stays
// disabled, so the window shows what a PNG holds.
#include "../common/shared.h"
#include "../common/tonemap.glsl"

layout(binding = BIND_TEX_PRESENT_SOURCE) uniform sampler2D source;
// 1 / the scene's pre-exposure (scene/Exposure.h) for radiance, 1 for debug views.
layout(location = LOC_PRESENT_SCALE) uniform float scale = 1.0;
layout(location = LOC_PRESENT_EXPOSURE) uniform float exposure = 1.0;
layout(location = LOC_PRESENT_CURVE) uniform int curve = TONE_CURVE_NONE;

in vec2 uv;
layout(location = 0) out vec4 outColor;

vec3 linearToSrgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
    vec3 radiance = texture(source, uv).rgb * scale;
    outColor = vec4(linearToSrgb(toneCurve(radiance * exposure, curve)), 1.0);
}
