// Forward pass, fragment stage: direct light from every light, plus emission and the GI
// technique's indirect light. Output is linear radiance (W/(m^2 sr)); alpha = 1 marks geometry.
// Per shadingModel() (frame.shading.z):
//   SHADING_LAMBERT: L = rho/pi * E + Le
//   SHADING_PHONG:   L = rho/pi * E + ks * (n+8)/(8 pi) * (N.H)^n * E + Le, in direct light
//                    only; the (n+8)/(8 pi) factor normalises the lobe so ks is an energy
//                    fraction
//   SHADING_GLTF:    L = f(v, l) * E + Le (brdf.glsl); indirect irradiance reflects with the
//                    diffuse term's weight under uniform light, and voxel GI's specular cone
//                    (already weighted by the specular albedo) is added to it
#include "../common/brdf.glsl"
#include "../common/frame.glsl"
#include "../common/lighting.glsl"
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#include "../common/direct_visibility.glsl"

layout(binding = BIND_TEX_INDIRECT) uniform sampler2D indirectTexture;
layout(binding = BIND_TEX_INDIRECT_SPECULAR) uniform sampler2D indirectSpecularTexture;
layout(location = LOC_FORWARD_INDIRECT_SIZE) uniform vec2 indirectSize;   // (0, 0): none
layout(location = LOC_FORWARD_INDIRECT_SPECULAR) uniform int hasIndirectSpecular;

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outRadiance;

// How sharply a texel's distance from the pixel's plane, relative to the pixel's depth, lowers
// its weight beside the bilinear one (to a tenth at 0.5 %); on the pixel's plane the texels
// differ from it by the half-float depth's rounding (0.05 %).
const float kUpsamplePlaneSharpness = 4e5;

// View depth (m) where the ray through screen point uv meets the plane through `position`
// facing n; 0 where the ray runs along the plane.
float planeDepthAt(vec2 uv, vec3 position, vec3 n) {
    vec4 far = frame.inverseViewProjection * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 ray = far.xyz / far.w - frame.cameraPosition.xyz;
    float along = dot(n, ray);
    if (abs(along) < 1e-9) return 0.0;
    vec3 forward = -vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
    return dot(n, position - frame.cameraPosition.xyz) / along * dot(ray, forward);
}

// Indirect light of this pixel's surface from one of the GI technique's screen-space textures,
// which may be smaller than the output. Bilinear (the thesis) or depth-aware: the four
// nearest texels weighted bilinearly and by how close their view depth is to this pixel's,
// so light does not bleed across depth edges, and (UPSAMPLE_DEPTH_PLANE) by how far each lies
// from the pixel's own plane (`position`, facing n), so it does not bleed across edges where
// two surfaces meet at one depth (a wall and the ceiling: accuracy-analysis.md); empty texels
// (a = 0) never count.
// The program is built per mode (FRAME_UPSAMPLE, render/FrameSwitches.h): llvmpipe runs the
// plane's four ray-plane meets per pixel whether a uniform says to or not (x1.28 of the
// Cornell box's forward pass).
int upsampleMode() {
#ifdef FRAME_UPSAMPLE
    return FRAME_UPSAMPLE;
#else
    return frame.counts.w;
#endif
}

vec3 upsampledIndirect(sampler2D indirectTexture, float viewDepth, vec3 position, vec3 n) {
    vec2 uv = gl_FragCoord.xy / frame.screen.xy;
    if (upsampleMode() == UPSAMPLE_BILINEAR) return texture(indirectTexture, uv).rgb;
    bool byPlane = upsampleMode() == UPSAMPLE_DEPTH_PLANE;
    vec2 p = uv * indirectSize - 0.5;
    vec2 f = fract(p);
    ivec2 base = ivec2(floor(p));
    ivec2 maxTexel = ivec2(indirectSize) - 1;
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 texel = clamp(base + o, ivec2(0), maxTexel);
        vec4 t = texelFetch(indirectTexture, texel, 0);
        if (t.a <= 0.0) continue;
        float bilinear = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        float scale = 1.0 / max(viewDepth, 1e-6);
        float relative = abs(t.a - viewDepth) * scale;
        float offPlane = 0.0;
        if (byPlane) {
            offPlane = abs(t.a - planeDepthAt((vec2(texel) + 0.5) / indirectSize, position, n)) *
                    scale;
        }
        float w = (bilinear + 1e-3) / (1e-3 + relative * relative * 400.0 +
                                             offPlane * offPlane * kUpsamplePlaneSharpness);
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
    int model = shadingModel();
    GltfSurface surface = gltfSurface(baseColor.rgb, m.metallicRoughness.x, m.metallicRoughness.y);
    uint random = hash(uint(gl_FragCoord.y) * 65536u + uint(gl_FragCoord.x));
    for (int i = 0; i < frame.counts.x; ++i) {
        vec3 e = lightIrradiance(lights[i], vin.position, n);
        if (all(equal(e, vec3(0.0)))) continue;
        vec3 toLight;
        float distance;
        lightDirection(lights[i], vin.position, toLight, distance);
        e *= directVisibility(i, vin.position, n, distance, random);
        if (model == SHADING_GLTF) {
            radiance += gltfBrdf(surface, n, toEye, toLight) * e;
            continue;
        }
        radiance += baseColor.rgb / PI * e;
        if (model == SHADING_PHONG) {
            vec3 h = normalize(toLight + toEye);
            radiance += ks * (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess) * e;
        }
    }
    // What uniform incident irradiance reflects, per unit of rho/pi.
    vec3 diffuse = model == SHADING_GLTF ? diffuseIndirectWeight(surface, dot(n, toEye))
                                         : baseColor.rgb;
    vec3 indirect = vec3(0.0);
    if (indirectSize.x > 0.0) {
        float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
        indirect = diffuse / PI * upsampledIndirect(indirectTexture, viewDepth, vin.position, n);
        if (model == SHADING_GLTF && hasIndirectSpecular != 0) {
            indirect += upsampledIndirect(indirectSpecularTexture, viewDepth, vin.position, n);
        }
    } else {
        // Without GI nothing tells where the sky is visible: it lights every surface as an
        // open hemisphere over a black ground would, E = pi L (1 + n.y) / 2 (exact for an
        // open floor, half for an open wall). With GI the gather sees it (cones, atlas).
        radiance += diffuse * frame.sky.rgb * 0.5 * (1.0 + n.y);
    }
    if (frame.counts.y == OUTPUT_INDIRECT) radiance = indirect;
    else if (frame.counts.y == OUTPUT_FINAL) radiance += indirect;
    outRadiance = vec4(radiance, 1.0);
}
