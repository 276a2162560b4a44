// Forward pass, fragment stage: Lambertian + optional Blinn-Phong direct light from every
// light, plus emission. Output is linear radiance (W/(m^2 sr)); alpha = 1 marks geometry.
//   L = rho/pi * E + ks * (n+8)/(8 pi) * (N.H)^n * E + Le
// The (n+8)/(8 pi) factor normalises the Blinn-Phong lobe so ks is an energy fraction.
#include "../common/frame.glsl"
#include "../common/lighting.glsl"
#include "../common/material.glsl"
#include "../common/shadows.glsl"

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

in VertexData {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
} vin;

layout(location = 0) out vec4 outRadiance;

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;

    vec3 n = normalize(vin.normal);
    vec3 toEye = normalize(frame.cameraPosition.xyz - vin.position);
    // Seen from behind (double-sided or culling off), a surface is lit on the viewer's side.
    if (!gl_FrontFacing) n = -n;

    vec3 radiance = materialEmission(m, vin.texcoord0);
    float ks = frame.shading.x, shininess = frame.shading.y;
    for (int i = 0; i < frame.counts.x; ++i) {
        vec3 e = lightIrradiance(lights[i], vin.position, n);
        if (all(equal(e, vec3(0.0)))) continue;
        vec3 toLight;
        float distance;
        lightDirection(lights[i], vin.position, toLight, distance);
        if (frame.shading.w != 0.0) e *= shadowVisibility(i, vin.position, n, distance);
        radiance += baseColor.rgb / PI * e;
        if (frame.shading.z != 0.0) {
            vec3 h = normalize(toLight + toEye);
            radiance += ks * (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess) * e;
        }
    }
    // Without a GI technique the indirect component is zero.
    if (frame.counts.y == OUTPUT_INDIRECT) radiance = vec3(0.0);
    outRadiance = vec4(radiance, 1.0);
}
