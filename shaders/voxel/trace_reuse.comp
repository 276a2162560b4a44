// Trace reuse (voxel.trace_reuse, gi/voxel/TraceReusePass.h): this frame traced one pixel of
// every 2x2 block of the trace (the pixel `phase`, in turn); every pixel of the full trace
// gets its E_ind here:
//   - the traced pixel: this frame's cones;
//   - the other three: the previous frame's result where the pixel's surface point projects
//     into the previous view, filtered bilinearly over the texels that saw the same surface
//     (view depth within kDepthTolerance). A still camera finds each pixel's own value, so
//     after four frames the image is the full trace's;
//   - where no history holds the surface (newly seen): the traced pixel of the four nearest
//     blocks whose view depth is closest to the pixel's.
// A frame that traced every pixel (stride 1: the first, or after the voxels' light changed)
// is copied as it is.
#include "../common/bilinear_taps.glsl"
#include "../common/frame.glsl"

layout(local_size_x = TRACE_REUSE_LOCAL_SIZE, local_size_y = TRACE_REUSE_LOCAL_SIZE) in;

layout(binding = BIND_TEX_REUSE_TRACED) uniform sampler2D traced;
layout(binding = BIND_TEX_REUSE_DEPTH) uniform sampler2D surfaceDepth;
layout(binding = BIND_TEX_REUSE_HISTORY) uniform sampler2D history;
layout(binding = BIND_IMG_REUSE_TARGET, rgba16f) writeonly uniform image2D target;

layout(location = LOC_REUSE_PREVIOUS_VIEW_PROJECTION) uniform mat4 previousViewProjection;
layout(location = LOC_REUSE_PREVIOUS_VIEW) uniform mat4 previousView;
layout(location = LOC_REUSE_PHASE) uniform ivec4 phase;

const float kDepthTolerance = 0.05;    // relative view-depth difference still the same surface

// The world point behind `texel` at window depth `depth` (the depth pre-pass, [0, 1]).
vec3 worldPoint(ivec2 texel, float depth, vec2 size) {
    vec3 ndc = vec3((vec2(texel) + 0.5) / size, depth) * 2.0 - 1.0;
    vec4 p = frame.inverseViewProjection * vec4(ndc, 1.0);
    return p.xyz / p.w;
}

// The previous result's value for `world`: its four nearest texels bilinearly, each only
// where the previous frame saw the same surface; w = 0 where none did.
vec4 previousValue(vec3 world, ivec2 size) {
    vec4 clip = previousViewProjection * vec4(world, 1.0);
    if (clip.w <= 0.0) return vec4(0.0);
    BilinearTaps taps = bilinearTaps(clip.xy / clip.w * 0.5 + 0.5, size);
    float expected = -(previousView * vec4(world, 1.0)).z;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec2 t = tapTexel(taps, i);
        if (!tapInside(t, size)) continue;
        vec4 h = texelFetch(history, t, 0);
        if (h.a <= 0.0 || abs(h.a - expected) > kDepthTolerance * expected) continue;
        float w = tapWeight(taps, i);
        sum += vec4(w * h.rgb, w);
    }
    return sum.a > 0.0 ? vec4(sum.rgb / sum.a, 1.0) : vec4(0.0);
}

// This frame's traced value nearest in depth among the four blocks around `texel`.
vec3 nearestTraced(ivec2 texel, float viewDepth) {
    ivec2 tracedSize = textureSize(traced, 0);
    ivec2 base = (texel - phase.xy) >> 1;
    vec3 best = vec3(0.0);
    float bestGap = 1e30;
    for (int i = 0; i < 4; ++i) {
        ivec2 t = clamp(base + ivec2(i & 1, i >> 1), ivec2(0), tracedSize - 1);
        vec4 v = texelFetch(traced, t, 0);
        if (v.a <= 0.0 || abs(v.a - viewDepth) >= bestGap) continue;
        bestGap = abs(v.a - viewDepth);
        best = v.rgb;
    }
    return best;
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(target);
    if (any(greaterThanEqual(texel, size))) return;
    if (phase.w == 1) {   // a full trace: every pixel traced, kept as the next history
        imageStore(target, texel, texelFetch(traced, texel, 0));
        return;
    }
    if ((texel & 1) == phase.xy) {
        imageStore(target, texel, texelFetch(traced, texel >> 1, 0));
        return;
    }
    float depth = texelFetch(surfaceDepth, texel, 0).r;
    if (depth >= 1.0) {
        imageStore(target, texel, vec4(0.0));
        return;
    }
    vec3 world = worldPoint(texel, depth, vec2(size));
    float viewDepth = -(frame.view * vec4(world, 1.0)).z;
    vec4 previous = phase.z != 0 ? previousValue(world, size) : vec4(0.0);
    vec3 irradiance = previous.a > 0.0 ? previous.rgb : nearestTraced(texel, viewDepth);
    imageStore(target, texel, vec4(irradiance, viewDepth));
}
