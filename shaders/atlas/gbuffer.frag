// Atlas G-buffer, fragment stage (thesis 4.4, eq. 5 and 6): one fragment per atlas texel of a
// surface, writing four layers (shared.h, BIND_TEX_ATLAS_*):
//   direct   the surface's outgoing direct radiance L = rho/pi * E + L_emitted, E summed over
//            every light with the forward pass's conventions and shadow maps (Lambert only;
//            the specular term is not part of what a diffuse surface sends on),
//   normal   unit normal, w = 1 for double-sided materials,
//   position world position; w = the surface area this texel stands for when the gather
//            samples it, |dP/dx x dP/dy| (exact for the planar triangle: in atlas space one
//            pixel step is one texel), written by the exact draw only,
//   albedo   rho.
// Double-sided surfaces hold one value per point: each light lights the side it faces.
#include "../common/frame.glsl"
#include "../common/lighting.glsl"
#include "../common/material.glsl"
#include "../common/shadows.glsl"

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

in AtlasVertex {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
    float doubleSided;
} vin;

#ifdef CONSERVATIVE
flat in vec4 texelBounds;
#endif

layout(location = 0) out vec4 outDirect;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outAlbedo;

void main() {
#ifdef CONSERVATIVE
    vec2 texelMin = gl_FragCoord.xy - 0.5, texelMax = gl_FragCoord.xy + 0.5;
    bool outside = any(greaterThan(texelMin, texelBounds.zw)) ||
                   any(lessThan(texelMax, texelBounds.xy));
    if (outside) discard;
    float sampleArea = 0.0;
#else
    // Derivatives before any discard (they need the whole 2x2 quad).
    float sampleArea = length(cross(dFdx(vin.position), dFdy(vin.position)));
#endif
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;

    float nLength = length(vin.normal);
    vec3 n = nLength > 0.0 ? vin.normal / nLength : vec3(0.0, 1.0, 0.0);
    bool doubleSided = vin.doubleSided > 0.5;
    vec3 e = vec3(0.0);
    for (int i = 0; i < frame.counts.x; ++i) {
        vec3 toLight;
        float distance;
        lightDirection(lights[i], vin.position, toLight, distance);
        vec3 lit = doubleSided && dot(n, toLight) < 0.0 ? -n : n;
        vec3 li = lightIrradiance(lights[i], vin.position, lit);
        if (all(equal(li, vec3(0.0)))) continue;
        if (frame.shading.w != 0.0) li *= shadowVisibility(i, vin.position, lit, distance);
        e += li;
    }
    vec3 radiance = baseColor.rgb / PI * e + materialEmission(m, vin.texcoord0);
    outDirect = vec4(radiance, 1.0);
    outNormal = vec4(n, doubleSided ? 1.0 : 0.0);
    outPosition = vec4(vin.position, sampleArea);
    outAlbedo = vec4(baseColor.rgb, 1.0);
}
