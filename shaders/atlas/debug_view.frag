// Atlas debug views: one atlas layer mapped onto the scene from the camera. G-buffer layers
// are read at the texel under the pixel's atlas coordinate (no filtering, so the view shows
// what the gather reads); the indirect layer bilinearly, as the resolve reads it. Direct and
// indirect show the side the camera sees (atlas_side.glsl).
//   direct    outgoing direct radiance L = rho/pi E + L_emitted (compare --output direct
//             with material.specular=0)
//   normal    0.5 + 0.5 n
//   position  world position in metres
//   albedo    rho
//   indirect  E_ind / pi: the radiance of a white diffuser (as the voxel irradiance view)
//   charts    a random colour per chart
#include "../common/constants.glsl"
#include "../common/frame.glsl"
#include "../common/material.glsl"
#include "atlas_common.glsl"
#include "atlas_side.glsl"
#include "atlas_vertex.glsl"

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;
layout(binding = BIND_TEX_ATLAS_ALBEDO) uniform sampler2D atlasAlbedo;
layout(binding = BIND_TEX_ATLAS_LIT) uniform sampler2D atlasLit;
layout(binding = BIND_TEX_ATLAS_DIRECT_BACK) uniform sampler2D atlasDirectBack;
layout(binding = BIND_TEX_ATLAS_LIT_BACK) uniform sampler2D atlasLitBack;

in ResolveVertex { RESOLVE_VERTEX_MEMBERS } vin;

layout(location = 0) out vec4 outColor;

vec3 chartColor(uint id) {
    // PCG-style integer hash to a saturated colour.
    uint h = id * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    vec3 c = vec3(h & 0xffu, (h >> 8u) & 0xffu, (h >> 16u) & 0xffu) / 255.0;
    return 0.15 + 0.85 * c;
}

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    int resolution = atlas.size.x;
    ivec2 texel = clamp(ivec2(floor(vin.atlasUv * float(resolution))), ivec2(0),
            ivec2(resolution - 1));
    bool back = cameraSeesBack(vin.position, vin.normal, vin.doubleSided);
    vec3 color;
    switch (atlas.size.w) {
    case ATLAS_VIEW_DIRECT:
        color = back ? texelFetch(atlasDirectBack, texel, 0).rgb
                     : texelFetch(atlasDirect, texel, 0).rgb;
        break;
    case ATLAS_VIEW_NORMAL: color = 0.5 + 0.5 * texelFetch(atlasNormal, texel, 0).xyz; break;
    case ATLAS_VIEW_POSITION: color = texelFetch(atlasPosition, texel, 0).xyz; break;
    case ATLAS_VIEW_ALBEDO: color = texelFetch(atlasAlbedo, texel, 0).rgb; break;
    case ATLAS_VIEW_INDIRECT:
        color = (back ? texture(atlasLitBack, vin.atlasUv).rgb
                      : texture(atlasLit, vin.atlasUv).rgb) / PI;
        break;
    default: color = chartColor(uint(vin.chart + 0.5)); break;
    }
    outColor = vec4(color, 1.0);
}
