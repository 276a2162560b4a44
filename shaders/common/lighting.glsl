// Direct irradiance from punctual lights, per DESIGN.md's radiometric conventions:
//   point:       E = I cos(theta) / d^2
//   spot:        E = I cos(theta) / d^2 * s^2,
//                s = clamp((cos(alpha) - cos(outer)) / (cos(inner) - cos(outer)), 0, 1)
//   directional: E = I cos(theta)
//   area:        E = sum over its triangles of L x the triangle's projected solid angle,
//                exact (Lambert's formula for a polygon, after clipping the triangle to the
//                surface's upper hemisphere)
//   sky:         none here: escaping cones and gather rays see it (its E needs visibility)
// Pure inverse square: the glTF range never attenuates. Shadowing is applied by the caller.
#ifndef GI_LIGHTING_GLSL
#define GI_LIGHTING_GLSL

#include "constants.glsl"
#include "shared.h"

layout(std430, binding = BIND_SSBO_LIGHTS) readonly buffer LightBlock {
    GpuLight lights[];
};

layout(std430, binding = BIND_SSBO_EMITTERS) readonly buffer EmitterBlock {
    GpuEmitter emitters[];
};

// Projected solid angle of a polygon given by its corners relative to the receiver, all in
// the receiver's upper hemisphere (Lambert 1760; e.g. Arvo 1995, "Applications of irradiance
// tensors", eq. 8): |sum over edges of Theta_i (n . unit(v_i x v_i+1))| / 2, where Theta_i is
// the angle the edge subtends. atan2 keeps small angles exact where acos would not.
float polygonProjectedSolidAngle(vec3 v[4], int count, vec3 n) {
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 a = v[i], b = v[(i + 1) % count];
        vec3 c = cross(a, b);
        float sine = length(c);
        if (sine <= 0.0) continue;
        sum += atan(sine, dot(a, b)) * dot(n, c) / sine;
    }
    return 0.5 * abs(sum);
}

// Irradiance from one emitting triangle on a surface at `position` with unit normal n.
vec3 emitterIrradiance(GpuEmitter e, vec3 position, vec3 n) {
    vec3 corner[3] = vec3[3](e.p0.xyz - position, e.p1.xyz - position, e.p2.xyz - position);
    vec3 front = cross(corner[1] - corner[0], corner[2] - corner[0]);
    // The receiver sees the front side when it lies on the side the front normal points to.
    if (e.radiance.w == 0.0 && dot(front, -corner[0]) <= 0.0) return vec3(0.0);
    // Clip the triangle to the half-space n . v >= 0 (Sutherland-Hodgman: a triangle cut by
    // a plane keeps at most four corners).
    vec3 clipped[4];
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        vec3 a = corner[i], b = corner[(i + 1) % 3];
        float da = dot(n, a), db = dot(n, b);
        if (da >= 0.0 && count < 4) clipped[count++] = a;
        if ((da >= 0.0) != (db >= 0.0) && count < 4) clipped[count++] = a + (b - a) * (da / (da - db));
    }
    if (count < 3) return vec3(0.0);
    return e.radiance.rgb * polygonProjectedSolidAngle(clipped, count, n);
}

// Unit vector from the surface towards the light, and the distance (inf for directional).
// Whether the scene has a light of `type` (LIGHT_*). llvmpipe runs every branch of a shader for
// all pixels of a group whenever one of them takes it, so the code of each kind of light ran
// for every light: a program built with FRAME_LIGHT_KINDS (render/FrameSwitches.h) drops the
// kinds the scene has none of. Without it every kind may be present.
bool lightsOfKind(int type) {
#ifdef FRAME_LIGHT_KINDS
    return (FRAME_LIGHT_KINDS & (1 << type)) != 0;
#else
    return true;
#endif
}

void lightDirection(GpuLight light, vec3 position, out vec3 toLight, out float distance) {
    int type = int(light.positionAndType.w);
    if (lightsOfKind(LIGHT_SKY) && type == LIGHT_SKY) {
        toLight = vec3(0.0, 1.0, 0.0);
        distance = 1.0 / 0.0;
    } else if (lightsOfKind(LIGHT_DIRECTIONAL) && type == LIGHT_DIRECTIONAL) {
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
    if (lightsOfKind(LIGHT_DIRECTIONAL) && type == LIGHT_DIRECTIONAL) {
        return light.radiantIntensity.rgb * cosTheta;
    }
    if (lightsOfKind(LIGHT_SKY) && type == LIGHT_SKY) return vec3(0.0);
    if (lightsOfKind(LIGHT_AREA) && type == LIGHT_AREA) {
        vec3 e = vec3(0.0);
        int first = int(light.spotCone.x), count = int(light.spotCone.y);
        for (int i = first; i < first + count; ++i) e += emitterIrradiance(emitters[i], position, n);
        return e;
    }
    // A surface point (almost) at the light would divide by ~0: those points are a singularity
    // of the point-light model, not a physical answer. The bound is relative to the scene
    // (spotCone.z = (1e-4 x its diagonal)^2, GpuScene.cpp), so scaled scenes light alike.
    float invSquare = 1.0 / max(distance * distance, light.spotCone.z);
    vec3 e = light.radiantIntensity.rgb * cosTheta * invSquare;
    if (lightsOfKind(LIGHT_SPOT) && type == LIGHT_SPOT) {
        float cosAlpha = dot(-toLight, light.directionAndRange.xyz);
        float cosInner = light.spotCone.x, cosOuter = light.spotCone.y;
        float s = clamp((cosAlpha - cosOuter) / max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
        e *= s * s;
    }
    return e;
}

#endif
