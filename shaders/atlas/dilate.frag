// Normalises the gather sums (x 1/N over every set so far) into E_ind and dilates it into the
// gutters: an empty texel takes the mean of the written texels in the nearest non-empty ring
// around it, up to atlas.dilation.x texels away. Bilinear lookups at chart borders then read
// the chart's own light instead of black (the thesis' flickering black seams, 5.1); the
// gutter keeps two charts' dilations apart. The back sides' sums (atlas.dilation.y = 1) are
// dilated the same way into their own layer.
#include "atlas_common.glsl"

layout(binding = BIND_TEX_ATLAS_SUMS) uniform sampler2D atlasSums;
layout(binding = BIND_TEX_ATLAS_SUMS_BACK) uniform sampler2D atlasSumsBack;

layout(location = 0) out vec4 outLit;
layout(location = 1) out vec4 outLitBack;

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
    outLit = dilated(atlasSums, texel);
    outLitBack = atlas.dilation.y > 0.5 ? dilated(atlasSumsBack, texel) : vec4(0.0);
}
