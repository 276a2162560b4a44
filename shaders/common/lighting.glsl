// Direct irradiance from punctual lights, per DESIGN.md's radiometric conventions:
//   point:       E = I cos(theta) / d^2
//   spot:        E = I cos(theta) / d^2 * s^2,
//                s = clamp((cos(alpha) - cos(outer)) / (cos(inner) - cos(outer)), 0, 1)
//   directional: E = I cos(theta)
// Pure inverse square: the glTF range never attenuates. Shadowing is applied by the caller.
#ifndef GI_LIGHTING_GLSL
#define GI_LIGHTING_GLSL

#include "constants.glsl"
#include "shared.h"

layout(std430, binding = BIND_SSBO_LIGHTS) readonly buffer LightBlock {
    GpuLight lights[];
};

// Unit vector from the surface towards the light, and the distance (inf for directional).
void lightDirection(GpuLight light, vec3 position, out vec3 toLight, out float distance) {
    if (int(light.positionAndType.w) == LIGHT_DIRECTIONAL) {
        toLight = -light.directionAndRange.xyz;
        distance = 1.0 / 0.0;
    } else {
        vec3 d = light.positionAndType.xyz - position;
        distance = length(d);
        toLight = distance > 0.0 ? d / distance : vec3(0.0, 1.0, 0.0);
    }
}

// Irradiance (W/m^2 per channel) before shadowing, on a surface with unit normal n.
vec3 lightIrradiance(GpuLight light, vec3 position, vec3 n) {
    vec3 toLight;
    float distance;
    lightDirection(light, position, toLight, distance);
    float cosTheta = max(dot(n, toLight), 0.0);
    int type = int(light.positionAndType.w);
    if (type == LIGHT_DIRECTIONAL) return light.radiantIntensity.rgb * cosTheta;
    // A surface point (almost) at the light would divide by ~0: those points are a singularity
    // of the point-light model, not a physical answer. The bound is relative to the scene
    // (spotCone.z = (1e-4 x its diagonal)^2, GpuScene.cpp), so scaled scenes light alike.
    float invSquare = 1.0 / max(distance * distance, light.spotCone.z);
    vec3 e = light.radiantIntensity.rgb * cosTheta * invSquare;
    if (type == LIGHT_SPOT) {
        float cosAlpha = dot(-toLight, light.directionAndRange.xyz);
        float cosInner = light.spotCone.x, cosOuter = light.spotCone.y;
        float s = clamp((cosAlpha - cosOuter) / max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
        e *= s * s;
    }
    return e;
}

#endif
