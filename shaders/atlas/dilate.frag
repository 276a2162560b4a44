// Normalises the gather sums (x 1/N over every set so far) into E_ind and dilates it into the
// gutters: an empty texel takes the mean of the written texels in the nearest non-empty ring
// around it, up to atlas.dilation.x texels away. Bilinear lookups at chart borders then read
// the chart's own light instead of black (the thesis' flickering black seams, 5.1); the
// gutter keeps two charts' dilations apart. The back sides' sums (atlas.dilation.y = 1) are
// dilated the same way into their own layer.
// With atlas.filter (atlas.dilation.z = 1) a written texel takes the tent-weighted mean of the
// written texels of its 3x3 block that lie on its own surface (surface_mask.frag): the same
// facing (normals within 18 degrees), its plane (within a fifth of a texel edge) and adjacent
// (within two edges).
// A receiver near a concave edge draws the adjacent face's nearby texels rarely, so its
// estimate is usually too dark and now and then far too bright; its neighbours draw their own
// senders, and the tent-weighted mean keeps about a seventh of their variance. Light that
// changes across a texel or two (contact shadows) is softened by about a texel.
#include "atlas_common.glsl"

layout(binding = BIND_TEX_ATLAS_SUMS) uniform sampler2D atlasSums;
layout(binding = BIND_TEX_ATLAS_SUMS_BACK) uniform sampler2D atlasSumsBack;
layout(binding = BIND_TEX_ATLAS_SURFACE_MASK) uniform usampler2D atlasSurfaceMask;

layout(location = 0) out vec4 outLit;
layout(location = 1) out vec4 outLitBack;

// The tent weights of the written texels of texel's 3x3 block on its own surface (the centre
// weighs 4 whatever its area, edge neighbours 2, corners 1; 0 off the surface), in row order.
// Which neighbours lie on the surface was drawn with the G-buffer (surface_mask.frag).
void surfaceWeights(ivec2 texel, out float weights[9]) {
    uint mask = texelFetch(atlasSurfaceMask, texel, 0).r;
    for (int i = 0; i < 9; ++i) {
        ivec2 offset = ivec2(i % 3 - 1, i / 3 - 1);
        bool onSurface = i != 4 && (mask & (1u << uint(i < 4 ? i : i - 1))) != 0u;
        weights[i] = i == 4 ? 4.0 : onSurface ? float(4 >> (abs(offset.x) + abs(offset.y))) : 0.0;
    }
}

vec4 filtered(sampler2D sums, ivec2 texel, float weights[9]) {
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int i = 0; i < 9; ++i) {
        if (weights[i] <= 0.0) continue;
        vec4 s = texelFetch(sums, texel + ivec2(i % 3 - 1, i / 3 - 1), 0);
        if (s.a <= 0.0) continue;
        sum += weights[i] * s.rgb;
        total += weights[i];
    }
    return vec4(sum / total * atlas.sampling.w, 1.0);
}

vec4 dilated(sampler2D sums, ivec2 texel) {
    float scale = atlas.sampling.w;
    vec4 own = texelFetch(sums, texel, 0);
    if (own.a > 0.0) return vec4(own.rgb * scale, 1.0);
    ivec2 maxTexel = ivec2(atlas.size.x - 1);
    int radius = int(atlas.dilation.x);
    for (int ring = 1; ring <= radius; ++ring) {
        vec3 sum = vec3(0.0);
        float count = 0.0;
        for (int dy = -ring; dy <= ring; ++dy) {
            for (int dx = -ring; dx <= ring; ++dx) {
                if (max(abs(dx), abs(dy)) != ring) continue;
                ivec2 q = texel + ivec2(dx, dy);
                if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, maxTexel))) continue;
                vec4 s = texelFetch(sums, q, 0);
                if (s.a <= 0.0) continue;
                sum += s.rgb;
                count += 1.0;
            }
        }
        if (count > 0.0) return vec4(sum / count * scale, 0.5);
    }
    return vec4(0.0);
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    bool backSides = atlas.dilation.y > 0.5;
    if (atlas.dilation.z > 0.5 && texelFetch(atlasSums, texel, 0).a > 0.0) {
        float weights[9];
        surfaceWeights(texel, weights);
        outLit = filtered(atlasSums, texel, weights);
        outLitBack = backSides ? filtered(atlasSumsBack, texel, weights) : vec4(0.0);
        return;
    }
    outLit = dilated(atlasSums, texel);
    outLitBack = backSides ? dilated(atlasSumsBack, texel) : vec4(0.0);
}
