// Senders for the area estimator, drawn in proportion to the power they send, or with
// atlas.importance to that power times what a set of receivers can receive of it: the surfaces
// the camera sees (view) or the atlas' own surfaces (surfaces; AtlasSenderSamplingPass.h,
// sender_weight.glsl). A texel's power is a(y) mean(L(y)): its
// sample area (position.w, m^2) times the mean of its direct radiance over RGB, where the
// G-buffer wrote it (direct.a > 0); double-sided texels add their back side's (both sides send).
//   STEP_VIEW_SAMPLES one invocation per cell of an ATLAS_VIEW_SAMPLES_PER_SIDE^2 grid over the
//                the camera's image: the surface at the cell's centre, rebuilt from the view
//                depth the resolve pass wrote, and its normal from the neighbouring pixels'.
//   STEP_SURFACE_SAMPLES one invocation per point on the scene's triangles (SurfacePoints.h,
//                spread by area): its place and normal from GpuScene's posed vertices, weighed
//                by the area it stands for, both sides receiving if double-sided.
//   STEP_IMPORTANCE one invocation per atlas texel (x: the column, y: the row, so that a 4096^2
//                atlas stays within the 65535 work groups a dimension): for each side, the
//                gather's kernel without visibility, cos at the texel x cos at the receiver /
//                max(B, r^2), summed over the receivers (the VPLs' importance, results-vpl.md).
//   STEP_ROWS    one invocation per atlas row: prefix sums of the weights at the end of every
//                ATLAS_SENDER_BLOCK texels, and the row's sum (two sums, sender_weight.glsl).
//   STEP_PREFIX  one invocation: the row sums turned into prefix sums over rows.
//   STEP_POOL    one invocation per pool point j = stratum * ATLAS_POOL_STRIDE + k: the point
//                u = (stratum + fract((k + rotation) / ATLAS_POOL_STRIDE)) / N of the total,
//                found by binary search over the rows, then the row's blocks, then a scan of
//                one block; the texel holding it is the sender.
// Every sum runs in one invocation in a fixed order, so the points do not depend on thread
// scheduling.
#include "atlas_common.glsl"
#include "sender_weight.glsl"

layout(local_size_x = ATLAS_SENDER_LOCAL_SIZE) in;

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;
layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_DIRECT_BACK) uniform sampler2D atlasDirectBack;

layout(std430, binding = BIND_SSBO_ATLAS_SENDER_ROWS) buffer SenderRows {
    vec2 rowPower[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SENDER_BLOCKS) buffer SenderBlocks {
    vec2 blockPower[];
};
layout(std430, binding = BIND_SSBO_ATLAS_RECEIVERS) buffer Receivers {
    vec4 receivers[];   // per cell: position (w = its weight, 0 where no surface is), normal
                        // (w = 1: both sides receive)
};
layout(std430, binding = BIND_SSBO_ATLAS_SENDER_POOL) buffer SenderPool {
    uint pool[];
};

// The texel's pair of weights (sender_weight.glsl). Texels whose radiance overflowed the
// half-float layer (inf) are never drawn: one of them would make every sum infinite.
vec2 senderWeights(int x, int y) {
    ivec2 t = ivec2(x, y);
    vec4 direct = texelFetch(atlasDirect, t, 0);
    if (direct.a <= 0.0) return vec2(0.0);
    vec3 back = texelFetch(atlasNormal, t, 0).w > 0.5 ? texelFetch(atlasDirectBack, t, 0).rgb
                                                      : vec3(0.0);
    vec2 weights = max(texelFetch(atlasPosition, t, 0).w, 0.0) *
                   senderWeightsPerArea(direct.rgb, back, senderImportance(t));
    return any(isinf(weights)) || any(isnan(weights)) ? vec2(0.0) : weights;
}

int blocksPerRow(int resolution) {
    return (resolution + ATLAS_SENDER_BLOCK - 1) / ATLAS_SENDER_BLOCK;
}

#if defined(STEP_VIEW_SAMPLES)

#include "../common/frame.glsl"

// The resolve pass' output: a = the view depth (m) of the surface in each pixel, 0 = none.
layout(binding = BIND_TEX_INDIRECT) uniform sampler2D viewIndirect;

// The surface in `pixel`, on the ray through its centre at the view depth the resolve stored.
bool surfaceAt(ivec2 pixel, out vec3 position) {
    ivec2 size = textureSize(viewIndirect, 0);
    if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) return false;
    float depth = texelFetch(viewIndirect, pixel, 0).a;
    if (!(depth > 0.0)) return false;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 near = frame.inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 far = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 origin = near.xyz / near.w;
    vec3 direction = normalize(far.xyz / far.w - origin);
    vec3 forward = -vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
    vec3 eye = frame.cameraPosition.xyz;
    float along = dot(direction, forward);
    if (!(along > 0.0)) return false;
    position = origin + direction * ((depth - dot(origin - eye, forward)) / along);
    return true;
}

// The step from `centre` to the neighbour `offset` away, or to the one opposite (negated)
// when that one is missing or lies on another surface (its depth differs by more than 10 %).
bool tangentAt(ivec2 pixel, vec3 centre, ivec2 offset, out vec3 tangent) {
    float centreDepth = length(centre - frame.cameraPosition.xyz);
    for (int side = 0; side < 2; ++side) {
        ivec2 o = side == 0 ? offset : -offset;
        vec3 p;
        if (!surfaceAt(pixel + o, p)) continue;
        if (abs(length(p - frame.cameraPosition.xyz) - centreDepth) > 0.1 * centreDepth) continue;
        tangent = side == 0 ? p - centre : centre - p;
        return true;
    }
    return false;
}

void main() {
    int cell = int(gl_GlobalInvocationID.x);
    const int perSide = ATLAS_VIEW_SAMPLES_PER_SIDE;
    if (cell >= perSide * perSide) return;
    ivec2 size = textureSize(viewIndirect, 0);
    ivec2 pixel = min(ivec2((vec2(cell % perSide, cell / perSide) + 0.5) * vec2(size) /
                            float(perSide)), size - 1);
    vec3 position = vec3(0.0), normal = vec3(0.0);
    bool found = surfaceAt(pixel, position);
    if (found) {
        vec3 toEye = normalize(frame.cameraPosition.xyz - position);
        vec3 dx, dy;
        normal = toEye;   // where the neighbours cannot tell, the surface faces the eye
        if (tangentAt(pixel, position, ivec2(1, 0), dx) &&
                tangentAt(pixel, position, ivec2(0, 1), dy)) {
            vec3 n = cross(dx, dy);
            if (dot(n, n) > 0.0) normal = normalize(n) * (dot(n, toEye) < 0.0 ? -1.0 : 1.0);
        }
    }
    receivers[2 * cell] = vec4(position, found ? 1.0 : 0.0);
    receivers[2 * cell + 1] = vec4(normal, 0.0);
}

#elif defined(STEP_SURFACE_SAMPLES)

layout(std430, binding = BIND_SSBO_SCENE_VERTICES) readonly buffer SceneVertices {
    float sceneVertex[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SURFACE_POINTS) readonly buffer SurfacePoints {
    uint surfacePoint[];
};

// Position (xyz) or normal (with offset 3) of GpuScene vertex v: both lead its layout.
vec3 sceneVector(uint v, uint offset) {
    uint base = v * uint(SCENE_VERTEX_FLOATS) + offset;
    return vec3(sceneVertex[base], sceneVertex[base + 1u], sceneVertex[base + 2u]);
}

void main() {
    uint cell = gl_GlobalInvocationID.x;
    if (cell >= uint(atlas.importance.y)) return;
    uint base = cell * uint(SURFACE_POINT_UINTS);
    uvec3 v = uvec3(surfacePoint[base], surfacePoint[base + 1u], surfacePoint[base + 2u]);
    vec3 b = vec3(0.0, uintBitsToFloat(surfacePoint[base + 4u]),
                  uintBitsToFloat(surfacePoint[base + 5u]));
    b.x = 1.0 - b.y - b.z;
    vec3 position = b.x * sceneVector(v.x, 0u) + b.y * sceneVector(v.y, 0u) +
                    b.z * sceneVector(v.z, 0u);
    vec3 normal = b.x * sceneVector(v.x, 3u) + b.y * sceneVector(v.y, 3u) +
                  b.z * sceneVector(v.z, 3u);
    bool found = dot(normal, normal) > 0.0;
    receivers[2u * cell] = vec4(position, found ? atlas.importance.w : 0.0);
    receivers[2u * cell + 1u] = vec4(found ? normalize(normal) : vec3(0.0),
                                    surfacePoint[base + 3u] != 0u ? 1.0 : 0.0);
}

#elif defined(STEP_IMPORTANCE)

layout(binding = BIND_IMG_ATLAS_IMPORTANCE, rg32f) uniform writeonly image2D importanceImage;

void main() {
    int resolution = atlas.size.x;
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (t.x >= resolution || t.y >= resolution) return;
    vec2 importance = vec2(0.0);
    vec4 position = texelFetch(atlasPosition, t, 0);
    vec4 direct = texelFetch(atlasDirect, t, 0);
    // One bounce draws only texels that send direct light; further bounces send from every
    // surface.
    bool sends = atlas.importance.z > 0.5 || any(greaterThan(direct.rgb, vec3(0.0))) ||
                 any(greaterThan(texelFetch(atlasDirectBack, t, 0).rgb, vec3(0.0)));
    if (direct.a > 0.0 && position.w > 0.0 && sends) {
        vec4 normal = texelFetch(atlasNormal, t, 0);
        bool twoSided = normal.w > 0.5;
        int cells = int(atlas.importance.y);
        for (int k = 0; k < cells; ++k) {
            vec4 receiver = receivers[2 * k];
            if (receiver.w <= 0.0) continue;
            vec3 d = receiver.xyz - position.xyz;
            float r2 = dot(d, d);
            // |d| cos at the receiver and at the texel's front; the kernel is their product
            // over r^2 x max(B, r^2), without a square root.
            vec4 receiverNormal = receivers[2 * k + 1];
            float atReceiver = -dot(receiverNormal.xyz, d);
            if (receiverNormal.w > 0.5) atReceiver = abs(atReceiver);
            float atSender = dot(normal.xyz, d);
            if (!(r2 > 0.0) || atReceiver <= 0.0) continue;
            float kernel = receiver.w * atReceiver * abs(atSender) /
                           (r2 * max(r2, atlas.importance.w));
            if (atSender > 0.0) importance.x += kernel;
            else if (twoSided) importance.y += kernel;
        }
    }
    imageStore(importanceImage, t, vec4(importance, 0.0, 0.0));
}

#elif defined(STEP_ROWS)

void main() {
    int y = int(gl_GlobalInvocationID.x);
    int resolution = atlas.size.x;
    if (y >= resolution) return;
    int blocks = blocksPerRow(resolution);
    vec2 sum = vec2(0.0);
    for (int b = 0; b < blocks; ++b) {
        int end = min(resolution, (b + 1) * ATLAS_SENDER_BLOCK);
        for (int x = b * ATLAS_SENDER_BLOCK; x < end; ++x) sum += senderWeights(x, y);
        blockPower[y * blocks + b] = sum;
    }
    rowPower[y] = sum;
}

#elif defined(STEP_PREFIX)

void main() {
    if (gl_GlobalInvocationID.x != 0u) return;
    vec2 sum = vec2(0.0);
    for (int y = 0; y < atlas.size.x; ++y) {
        sum += rowPower[y];
        rowPower[y] = sum;
    }
}

#else // STEP_POOL

void main() {
    uint j = gl_GlobalInvocationID.x;
    int resolution = atlas.size.x;
    int samples = atlas.size.y;
    if (j >= uint(samples) * uint(ATLAS_POOL_STRIDE)) return;
    float floorPerPower = importanceFloor(rowPower[resolution - 1]);
    float total = combinedWeight(rowPower[resolution - 1], floorPerPower);
    if (!(total > 0.0)) {
        pool[j] = ~0u;
        return;
    }
    uint stratum = j / uint(ATLAS_POOL_STRIDE), k = j % uint(ATLAS_POOL_STRIDE);
    float offset = fract((float(k) + atlas.sampling.x) / float(ATLAS_POOL_STRIDE));
    float target = (float(stratum) + offset) / float(samples) * total;

    // The first row whose prefix sum exceeds the target.
    int lo = 0, hi = resolution - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (combinedWeight(rowPower[mid], floorPerPower) > target) hi = mid;
        else lo = mid + 1;
    }
    int y = lo;
    // A target rounded up to the total lands past the last row with area: step back to it.
    while (y > 0 && !(combinedWeight(rowPower[y], floorPerPower) >
                      combinedWeight(rowPower[y - 1], floorPerPower))) {
        --y;
    }
    int blocks = blocksPerRow(resolution);
    int base = y * blocks;
    float rest = target - (y > 0 ? combinedWeight(rowPower[y - 1], floorPerPower) : 0.0);
    // The first block of the row whose prefix sum exceeds the rest.
    lo = 0;
    hi = blocks - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (combinedWeight(blockPower[base + mid], floorPerPower) > rest) hi = mid;
        else lo = mid + 1;
    }
    // Scan from that block to the texel that takes the sum past the rest. Rounding of the
    // prefix sums can leave the rest at or past the row's sum: then the row's last texel with
    // area is the sender.
    float sum = lo > 0 ? combinedWeight(blockPower[base + lo - 1], floorPerPower) : 0.0;
    int chosen = -1, last = -1;
    for (int x = lo * ATLAS_SENDER_BLOCK; x < resolution && chosen < 0; ++x) {
        float a = combinedWeight(senderWeights(x, y), floorPerPower);
        if (a <= 0.0) continue;
        last = x;
        sum += a;
        if (sum > rest) chosen = x;
    }
    for (int x = lo * ATLAS_SENDER_BLOCK - 1; x >= 0 && last < 0; --x) {
        if (combinedWeight(senderWeights(x, y), floorPerPower) > 0.0) last = x;
    }
    if (chosen < 0) chosen = last;
    pool[j] = chosen < 0 ? ~0u : uint(y * resolution + chosen);
}

#endif
