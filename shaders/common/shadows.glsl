// Shadow-map visibility for one light, shared by every pass that shades with direct light.
// 2D maps (spot: perspective, directional: orthographic over the scene bounds) use hardware
// depth comparison with bilinear filtering plus a 3x3 PCF kernel; cube maps store distance
// to the light / far and are filtered with 4 comparison taps around the lookup direction.
// The lookup point is pushed along the normal by a few texels of the map's footprint at
// that distance (normal-offset bias), which removes acne without detaching contact shadows.
#ifndef GI_SHADOWS_GLSL
#define GI_SHADOWS_GLSL

#include "frame.glsl"
#include "lighting.glsl"

layout(std430, binding = BIND_SSBO_SHADOWS) readonly buffer ShadowBlock {
    GpuShadow shadows[];
};

layout(binding = BIND_TEX_SHADOW_2D) uniform sampler2DArrayShadow shadowMaps2D;
layout(binding = BIND_TEX_SHADOW_CUBE) uniform samplerCubeArrayShadow shadowMapsCube;

float shadowVisibility(int lightIndex, vec3 position, vec3 n, float distanceToLight) {
    GpuShadow s = shadows[lightIndex];
    int kind = int(s.params.x);
    if (kind == SHADOW_NONE) return 1.0;
    float layer = s.params.y;
    bool ortho = s.bias.z != 0.0;
    float texel = ortho ? s.params.w : s.params.w * distanceToLight;
    vec3 p = position + n * (s.bias.x * texel);

    if (kind == SHADOW_2D && shadowMapsOfKind(SHADOW_2D)) {
        vec4 clip = s.worldToShadow * vec4(p, 1.0);
        vec3 ndc = clip.xyz / clip.w;
        vec3 uvz = ndc * 0.5 + 0.5;
        if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0;
        if (uvz.z >= 1.0) return 1.0;
        vec2 texelUv = 1.0 / vec2(textureSize(shadowMaps2D, 0).xy);
        float sum = 0.0;
        for (int y = -1; y <= 1; ++y) {
            for (int x = -1; x <= 1; ++x) {
                vec2 uv = uvz.xy + vec2(x, y) * texelUv * s.bias.y;
                sum += texture(shadowMaps2D, vec4(uv, layer, uvz.z));
            }
        }
        return sum / 9.0;
    }

    if (!shadowMapsOfKind(SHADOW_CUBE)) return 1.0;   // no light has one: never reached
    vec3 fromLight = p - lights[lightIndex].positionAndType.xyz;
    float distance = length(fromLight);
    float reference = distance / s.params.z;
    vec3 dir = fromLight / max(distance, 1e-20);
    vec3 t = normalize(abs(dir.y) < 0.99 ? cross(dir, vec3(0.0, 1.0, 0.0)) : cross(dir, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(dir, t);
    float radius = s.bias.y * s.params.w;   // one texel of angle at unit distance
    float sum = 0.0;
    sum += texture(shadowMapsCube, vec4(dir + radius * ( t + b), layer), reference);
    sum += texture(shadowMapsCube, vec4(dir + radius * ( t - b), layer), reference);
    sum += texture(shadowMapsCube, vec4(dir + radius * (-t + b), layer), reference);
    sum += texture(shadowMapsCube, vec4(dir + radius * (-t - b), layer), reference);
    return sum * 0.25;
}

#endif
