// Temporal reprojection of the indirect irradiance: each texel's surface point is found from
// its view depth, projected into the previous frame, and the filter's previous output there
// is blended with this frame's value by an exponential moving average. History is rejected
// where the previous frame saw another surface (view depth or normal too different) or
// nothing; with gi.temporal_clamp it is also clamped to the range of this frame's 3x3
// neighbourhood, so light that changed (a moving object) cannot linger as a trail; the C++
// side leaves the clamp out while a step of the technique's own (a voxel cascade's snap) fades
// in (TemporalFilter.h).
// A texel's first frames average uniformly (weight 1/n) until n reaches 1/blend, so newly
// seen surfaces converge as fast as a plain mean would.
#include "../common/bilinear_taps.glsl"
#include "../common/frame.glsl"

layout(local_size_x = TEMPORAL_LOCAL_SIZE, local_size_y = TEMPORAL_LOCAL_SIZE) in;

layout(binding = BIND_TEX_TEMPORAL_CURRENT) uniform sampler2D current;
layout(binding = BIND_TEX_TEMPORAL_HISTORY) uniform sampler2D history;
layout(binding = BIND_TEX_TEMPORAL_HISTORY_NORMAL) uniform sampler2D historyNormal;
layout(binding = BIND_IMG_TEMPORAL_TARGET, rgba32f) writeonly uniform image2D target;
layout(binding = BIND_IMG_TEMPORAL_NORMAL, rgba16f) writeonly uniform image2D targetNormal;

layout(location = LOC_TEMPORAL_PREVIOUS_VIEW_PROJECTION) uniform mat4 previousViewProjection;
layout(location = LOC_TEMPORAL_PREVIOUS_VIEW) uniform mat4 previousView;
layout(location = LOC_TEMPORAL_PARAMETERS) uniform vec4 parameters;

const float kDepthTolerance = 0.05;    // relative view-depth difference still the same surface
const float kNormalTolerance = 0.9;    // smallest cosine between normals of the same surface

// The world point seen through `texel` at view depth `depth` (m) in this frame.
vec3 worldPoint(vec2 texel, float depth, vec2 size) {
    vec2 ndc = (texel + 0.5) / size * 2.0 - 1.0;
    vec4 a = frame.inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 b = frame.inverseViewProjection * vec4(ndc, 0.0, 1.0);
    a /= a.w;
    b /= b.w;
    float depthA = -(frame.view * vec4(a.xyz, 1.0)).z;
    float depthB = -(frame.view * vec4(b.xyz, 1.0)).z;
    return mix(a.xyz, b.xyz, (depth - depthA) / (depthB - depthA));
}

// The surface normal at `texel` from its neighbours' points, on each axis the side whose
// depth is closer (so a depth edge does not bend it); facing the camera.
vec3 surfaceNormal(ivec2 texel, vec3 centre, float depth, ivec2 size) {
    vec3 along[2];
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec3 best = vec3(0.0);
        float bestGap = 1e30;
        for (int side = -1; side <= 1; side += 2) {
            ivec2 p = texel + side * step;
            if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) continue;
            float d = texelFetch(current, p, 0).a;
            if (d <= 0.0 || abs(d - depth) >= bestGap) continue;
            bestGap = abs(d - depth);
            best = float(side) * (worldPoint(vec2(p), d, vec2(size)) - centre);
        }
        along[axis] = best;
    }
    vec3 n = cross(along[0], along[1]);
    if (dot(n, n) <= 0.0) return vec3(0.0);
    n = normalize(n);
    return dot(n, frame.cameraPosition.xyz - centre) < 0.0 ? -n : n;
}

// The reprojected history at `uv` of the previous frame: its four nearest texels bilinearly,
// each only where it saw the same surface. w = the history length, 0 = none.
vec4 reprojectedHistory(vec2 uv, float expectedDepth, vec3 normal, out vec3 irradiance) {
    ivec2 size = textureSize(history, 0);
    BilinearTaps taps = bilinearTaps(uv, size);
    vec3 sum = vec3(0.0);
    float frames = 0.0, weightSum = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 t = tapTexel(taps, i);
        if (!tapInside(t, size)) continue;
        vec4 h = texelFetch(history, t, 0);
        vec4 hn = texelFetch(historyNormal, t, 0);
        if (h.a <= 0.0 || abs(h.a - expectedDepth) > kDepthTolerance * expectedDepth) continue;
        if (dot(hn.xyz, normal) < kNormalTolerance) continue;
        float w = tapWeight(taps, i);
        sum += w * h.rgb;
        frames += w * hn.w;
        weightSum += w;
    }
    if (weightSum <= 0.0) {
        irradiance = vec3(0.0);
        return vec4(0.0);
    }
    irradiance = sum / weightSum;
    return vec4(irradiance, frames / weightSum);
}

// The range history may take: this frame's mean over the 3x3 texels around `texel` on the
// same surface, +- kClipSigmas standard deviations (variance clipping, Salvi 2016), within
// their minimum and maximum. Noise widens it; a change of the light itself falls outside.
const float kClipSigmas = 1.0;

void neighbourhoodRange(ivec2 texel, float depth, ivec2 size, out vec3 low, out vec3 high) {
    vec3 least = vec3(1e30), most = vec3(0.0), sum = vec3(0.0), squares = vec3(0.0);
    float count = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            ivec2 p = clamp(texel + ivec2(x, y), ivec2(0), size - 1);
            vec4 t = texelFetch(current, p, 0);
            if (t.a <= 0.0 || abs(t.a - depth) > kDepthTolerance * depth) continue;
            least = min(least, t.rgb);
            most = max(most, t.rgb);
            sum += t.rgb;
            squares += t.rgb * t.rgb;
            count += 1.0;
        }
    }
    vec3 mean = sum / count;
    vec3 sigma = sqrt(max(squares / count - mean * mean, vec3(0.0)));
    // The centre itself always lies inside, so a still view's history is never clipped.
    vec3 centre = texelFetch(current, texel, 0).rgb;
    low = min(max(least, mean - kClipSigmas * sigma), centre);
    high = max(min(most, mean + kClipSigmas * sigma), centre);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(current, 0);
    if (any(greaterThanEqual(texel, size))) return;
    vec4 now = texelFetch(current, texel, 0);
    if (now.a <= 0.0) {
        imageStore(target, texel, now);
        imageStore(targetNormal, texel, vec4(0.0));
        return;
    }
    vec3 point = worldPoint(vec2(texel), now.a, vec2(size));
    vec3 normal = surfaceNormal(texel, point, now.a, size);

    float blend = parameters.x;
    vec3 result = now.rgb;
    float frames = 1.0;
    vec4 clip = previousViewProjection * vec4(point, 1.0);
    if (parameters.y != 0.0 && clip.w > 0.0) {
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        float expectedDepth = -(previousView * vec4(point, 1.0)).z;
        vec3 previous;
        vec4 found = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))
                ? reprojectedHistory(uv, expectedDepth, normal, previous)
                : vec4(0.0);
        if (found.w > 0.0) {
            if (parameters.z != 0.0) {
                vec3 low, high;
                neighbourhoodRange(texel, now.a, size, low, high);
                previous = clamp(previous, low, high);
            }
            frames = min(found.w + 1.0, 1.0 / blend);
            result = mix(previous, now.rgb, max(blend, 1.0 / frames));
        }
    }
    imageStore(target, texel, vec4(result, now.a));
    imageStore(targetNormal, texel, vec4(normal, frames));
}
