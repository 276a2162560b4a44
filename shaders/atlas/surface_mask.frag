// Which neighbours of each written atlas texel lie on its own surface, for atlas.filter's
// tent-weighted mean (dilate.frag): the same facing (normals within 18 degrees), its plane
// (within a fifth of a texel edge) and adjacent (within two edges). The answer depends on the
// G-buffer alone, so it is drawn with the G-buffer instead of with every dilation.
// Output: bit i of the 3x3 block's neighbour i (row order, the centre left out: bits 0-3 are
// neighbours 0-3, bits 4-7 neighbours 5-8); 0 for empty texels.
#include "atlas_common.glsl"

layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;

layout(location = 0) out uint outMask;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(atlasPosition, texel, 0);
    outMask = 0u;
    if (p.w <= 0.0) return;
    vec3 n = texelFetch(atlasNormal, texel, 0).xyz;
    ivec2 maxTexel = ivec2(atlas.size.x - 1);
    for (int i = 0; i < 9; ++i) {
        ivec2 q = texel + ivec2(i % 3 - 1, i / 3 - 1);
        if (i == 4 || any(lessThan(q, ivec2(0))) || any(greaterThan(q, maxTexel))) continue;
        vec4 pq = texelFetch(atlasPosition, q, 0);
        if (pq.w <= 0.0) continue;
        vec3 d = pq.xyz - p.xyz;
        // A texel on a chart's border stands for part of its square (its w): the larger of
        // the two areas gives the texel edge.
        float edge = sqrt(max(p.w, pq.w));
        bool onSurface = dot(texelFetch(atlasNormal, q, 0).xyz, n) >= 0.95 &&
                abs(dot(d, n)) <= 0.2 * edge && dot(d, d) <= 4.0 * edge * edge;
        if (onSurface) outMask |= 1u << uint(i < 4 ? i : i - 1);
    }
}
