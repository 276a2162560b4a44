// Atlas G-buffer, fragment stage (thesis 4.4, eq. 5 and 6): one fragment per atlas texel of a
// surface, writing five layers (shared.h, BIND_TEX_ATLAS_*):
//   direct      the surface's outgoing direct radiance L = rho/pi * E + L_emitted on the side
//               the normal points to, E summed over every light with the forward pass's
//               conventions and shadow maps, rho what the surface sends on of each light
//               (reflectance.glsl: the base colour, or the glTF BRDF's albedo for the
//               light's direction), sent on as diffuse light,
//   direct back the same on the other side for double-sided materials (0 for single-sided),
//   normal      unit normal, w = 1 for double-sided materials,
//   position    world position; w = 0 (the SAMPLE_AREA draw adds the area, below),
//   albedo      rho of light from every direction alike (what further bounces reflect).
// The two sides of a double-sided surface are lit separately, each only by the lights in
// front of it, and both emit, as the path tracer shades them (its normal faces the ray).
// SAMPLE_AREA (a third draw, conservative, additive blending into position.w only): each
// triangle adds the world area of its part inside the texel square (the triangle clipped to
// the square, times the triangle's world area per texel^2), so w is the surface area the texel
// stands for as a gather sample and the texels' w add up to the scene's surface area at any
// resolution, charts smaller than a texel included.
#include "../common/frame.glsl"
#include "../common/lighting.glsl"
#include "../common/material.glsl"
#include "../common/reflectance.glsl"
#include "../common/shadows.glsl"
#include "atlas_vertex.glsl"

in AtlasVertex { ATLAS_VERTEX_MEMBERS } vin;

#ifdef CONSERVATIVE
flat in vec4 texelBounds;
#endif
#ifdef SAMPLE_AREA
flat in vec4 triangleAB;
flat in vec4 triangleC;

// Area (texel^2) of the triangle (a, b, c) inside the square [lo, lo + 1]^2, by Green's
// theorem over the boundary of the intersection (both convex, counter-clockwise): the parts
// of the triangle's edges inside the square (Liang-Barsky) and the parts of the square's edges
// inside the triangle each add cross(start, end) / 2. In coordinates relative to the square
// (float keeps slivers' areas there), only its right and top edges have a non-zero cross
// product (1 for the whole edge). Fixed work per texel, no arrays.
float clippedArea(vec2 a, vec2 b, vec2 c, vec2 lo) {
    vec2 v[3] = vec2[3](a - lo, b - lo, c - lo);
    float twiceSigned = (v[1].x - v[0].x) * (v[2].y - v[0].y) -
                        (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (twiceSigned < 0.0) {
        vec2 t = v[1];
        v[1] = v[2];
        v[2] = t;
    }
    float twice = 0.0;
    for (int i = 0; i < 3; ++i) {
        vec2 p = v[i], d = v[i == 2 ? 0 : i + 1] - p;
        // p + t d inside [0,1]^2 for t in [t0, t1].
        float t0 = 0.0, t1 = 1.0;
        for (int axis = 0; axis < 2; ++axis) {
            if (d[axis] == 0.0) {
                if (p[axis] < 0.0 || p[axis] > 1.0) t1 = -1.0;
            } else {
                float ta = -p[axis] / d[axis], tb = (1.0 - p[axis]) / d[axis];
                t0 = max(t0, min(ta, tb));
                t1 = min(t1, max(ta, tb));
            }
        }
        if (t1 > t0) twice += (p.x * d.y - p.y * d.x) * (t1 - t0);
    }
    // The square's right edge (1,0)->(1,1) and top edge (1,1)->(0,1) inside the triangle.
    for (int side = 0; side < 2; ++side) {
        vec2 s0 = side == 0 ? vec2(1.0, 0.0) : vec2(1.0, 1.0);
        vec2 s1 = side == 0 ? vec2(1.0, 1.0) : vec2(0.0, 1.0);
        float t0 = 0.0, t1 = 1.0;
        for (int i = 0; i < 3; ++i) {
            vec2 p = v[i], e = v[i == 2 ? 0 : i + 1] - p;
            float f0 = e.x * (s0.y - p.y) - e.y * (s0.x - p.x);
            float f1 = e.x * (s1.y - p.y) - e.y * (s1.x - p.x);
            // Strictly inside: a square edge along a triangle edge is counted once, as part
            // of the triangle's edge above.
            if (f0 <= 0.0 && f1 <= 0.0) {
                t1 = -1.0;
            } else if (f0 <= 0.0) {
                t0 = max(t0, f0 / (f0 - f1));
            } else if (f1 <= 0.0) {
                t1 = min(t1, f0 / (f0 - f1));
            }
        }
        if (t1 > t0) twice += t1 - t0;
    }
    return clamp(0.5 * twice, 0.0, min(1.0, 0.5 * abs(twiceSigned)));
}
#endif

layout(location = 0) out vec4 outDirect;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outAlbedo;
layout(location = 4) out vec4 outDirectBack;

#ifdef SAMPLE_AREA

void main() {
    GpuMaterial m = materials[drawMaterial];
    // The same cut-out as the other draws, at the texel centre.
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    float inside =
            clippedArea(triangleAB.xy, triangleAB.zw, triangleC.xy, floor(gl_FragCoord.xy));
    if (inside <= 0.0) discard;
    outPosition = vec4(0.0, 0.0, 0.0, inside * triangleC.z);
}

#else

// rho E: the direct irradiance on the side facing n, each light's times what the surface
// reflects of it.
vec3 reflectedIrradiance(GpuMaterial m, vec3 baseColor, vec3 n) {
    bool gltf = shadingModel() == SHADING_GLTF;
    vec3 e = vec3(0.0);
    for (int i = 0; i < frame.counts.x; ++i) {
        vec3 li = lightIrradiance(lights[i], vin.position, n);
        if (all(equal(li, vec3(0.0)))) continue;
        vec3 toLight;
        float distance;
        lightDirection(lights[i], vin.position, toLight, distance);
        if (shadowsApplied()) li *= shadowVisibility(i, vin.position, n, distance);
        e += li * reflectanceOfLight(m, baseColor, dot(n, toLight), gltf);
    }
    return e;
}

void main() {
#ifdef CONSERVATIVE
    vec2 texelMin = gl_FragCoord.xy - 0.5, texelMax = gl_FragCoord.xy + 0.5;
    bool outside = any(greaterThan(texelMin, texelBounds.zw)) ||
                   any(lessThan(texelMax, texelBounds.xy));
    if (outside) discard;
#endif
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;

    float nLength = length(vin.normal);
    vec3 n = nLength > 0.0 ? vin.normal / nLength : vec3(0.0, 1.0, 0.0);
    bool doubleSided = vin.doubleSided > 0.5;
    // Senders' emission is gathered as light, except where it already arrives as an area
    // light's direct light.
    vec3 emission = materialEmitsAsLight(m) ? vec3(0.0) : materialEmission(m, vin.texcoord0);
    outDirect = vec4(reflectedIrradiance(m, baseColor.rgb, n) / PI + emission, 1.0);
    outDirectBack = doubleSided ? vec4(reflectedIrradiance(m, baseColor.rgb, -n) / PI + emission, 1.0)
                                : vec4(0.0);
    outNormal = vec4(n, doubleSided ? 1.0 : 0.0);
    outPosition = vec4(vin.position, 0.0);
    outAlbedo = vec4(reflectanceOfUniformLight(m, baseColor.rgb, shadingModel() == SHADING_GLTF), 1.0);
}

#endif
