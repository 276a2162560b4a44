// Forward pass, fragment stage: Lambertian + optional Blinn-Phong direct light from every
// light, plus emission. Output is linear radiance (W/(m^2 sr)); alpha = 1 marks geometry.
//   L = rho/pi * E + ks * (n+8)/(8 pi) * (N.H)^n * E + Le
// The (n+8)/(8 pi) factor normalises the Blinn-Phong lobe so ks is an energy fraction.
#include "../common/frame.glsl"
#include "../common/lighting.glsl"
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#include "../common/direct_visibility.glsl"

layout(binding = BIND_TEX_INDIRECT) uniform sampler2D indirectTexture;
layout(location = LOC_FORWARD_INDIRECT_SIZE) uniform vec2 indirectSize;   // (0, 0): none

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outRadiance;

// Indirect irradiance E_ind of this pixel's surface from the GI technique's screen-space
// texture, which may be smaller than the output. Bilinear (the thesis) or depth-aware: the
// four nearest texels weighted bilinearly and by how close their view depth is to this
// pixel's, so light does not bleed across depth edges; empty texels (a = 0) never count.
vec3 indirectIrradiance(float viewDepth) {
    vec2 uv = gl_FragCoord.xy / frame.screen.xy;
    if (frame.counts.w == 0) return texture(indirectTexture, uv).rgb;
    vec2 p = uv * indirectSize - 0.5;
    vec2 f = fract(p);
    ivec2 base = ivec2(floor(p));
    ivec2 maxTexel = ivec2(indirectSize) - 1;
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        vec4 t = texelFetch(indirectTexture, clamp(base + o, ivec2(0), maxTexel), 0);
        if (t.a <= 0.0) continue;
        float bilinear = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        float relative = abs(t.a - viewDepth) / max(viewDepth, 1e-6);
        float w = (bilinear + 1e-3) / (1e-3 + relative * relative * 400.0);
        sum += w * t.rgb;
        weightSum += w;
    }
    return weightSum > 0.0 ? sum / weightSum : texture(indirectTexture, uv).rgb;
}

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;

    vec3 n = normalize(vin.normal);
    vec3 toEye = normalize(frame.cameraPosition.xyz - vin.position);
    // A surface is lit on the side the viewer sees (double-sided, or seen from behind with
    // culling off), the side its own normal faces from the eye, as in the path tracer: the
    // winding (gl_FrontFacing) picks the wrong side where normals point against it.
    if (dot(n, toEye) < 0.0) n = -n;

    vec3 radiance = materialEmission(m, vin.texcoord0);
    float ks = frame.shading.x, shininess = frame.shading.y;
    uint random = hash(uint(gl_FragCoord.y) * 65536u + uint(gl_FragCoord.x));
    for (int i = 0; i < frame.counts.x; ++i) {
        vec3 e = lightIrradiance(lights[i], vin.position, n);
        if (all(equal(e, vec3(0.0)))) continue;
        vec3 toLight;
        float distance;
        lightDirection(lights[i], vin.position, toLight, distance);
        e *= directVisibility(i, vin.position, n, distance, random);
        radiance += baseColor.rgb / PI * e;
        if (frame.shading.z != 0.0) {
            vec3 h = normalize(toLight + toEye);
            radiance += ks * (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess) * e;
        }
    }
    vec3 indirect = vec3(0.0);
    if (indirectSize.x > 0.0) {
        float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
        indirect = baseColor.rgb / PI * indirectIrradiance(viewDepth);
    } else {
        // Without GI nothing tells where the sky is visible: it lights every surface as an
        // open hemisphere over a black ground would, E = pi L (1 + n.y) / 2 (exact for an
        // open floor, half for an open wall). With GI the gather sees it (cones, atlas).
        radiance += baseColor.rgb * frame.sky.rgb * 0.5 * (1.0 + n.y);
    }
    if (frame.counts.y == OUTPUT_INDIRECT) radiance = indirect;
    else if (frame.counts.y == OUTPUT_FINAL) radiance += indirect;
    outRadiance = vec4(radiance, 1.0);
}
