// The four texels around a point of a texture and their bilinear weights, for filters that
// drop taps one by one (reprojected history that saw another surface): render/
// temporal_filter.comp and voxel/trace_reuse.comp.
#ifndef GI_BILINEAR_TAPS_GLSL
#define GI_BILINEAR_TAPS_GLSL

struct BilinearTaps {
    ivec2 base;   // the lower-left texel of the four
    vec2 f;       // the point's position between them
};

// uv in [0, 1] over a texture of `size` texels.
BilinearTaps bilinearTaps(vec2 uv, ivec2 size) {
    vec2 p = uv * vec2(size) - 0.5;
    BilinearTaps taps;
    taps.base = ivec2(floor(p));
    taps.f = p - vec2(taps.base);
    return taps;
}

ivec2 tapTexel(BilinearTaps taps, int i) { return taps.base + ivec2(i & 1, i >> 1); }

bool tapInside(ivec2 texel, ivec2 size) {
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, size));
}

// Tap i's weight, never quite zero, so a point on a texel's edge still takes that texel
// when its neighbour is dropped.
float tapWeight(BilinearTaps taps, int i) {
    vec2 w = mix(1.0 - taps.f, taps.f, vec2(i & 1, i >> 1));
    return w.x * w.y + 1e-4;
}

#endif
