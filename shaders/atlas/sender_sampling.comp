// Senders for the area estimator, drawn in proportion to the power they send
// (AtlasSenderSamplingPass.h). A texel's weight is a(y) mean(L(y)): its sample area
// (position.w, m^2) times the mean of its direct radiance over RGB, where the G-buffer wrote it
// (direct.a > 0); double-sided texels add their back side's mean radiance (both sides send).
//   STEP_ROWS    one invocation per atlas row: prefix sums of the weights at the end of every
//                ATLAS_SENDER_BLOCK texels, and the row's sum.
//   STEP_PREFIX  one invocation: the row sums turned into prefix sums over rows.
//   STEP_POOL    one invocation per pool point j = stratum * ATLAS_POOL_STRIDE + k: the point
//                u = (stratum + fract((k + rotation) / ATLAS_POOL_STRIDE)) / N of the total,
//                found by binary search over the rows, then the row's blocks, then a scan of
//                one block; the texel holding it is the sender.
// Every sum runs in one invocation in a fixed order, so the points do not depend on thread
// scheduling.
#include "atlas_common.glsl"

layout(local_size_x = ATLAS_SENDER_LOCAL_SIZE) in;

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;
layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_DIRECT_BACK) uniform sampler2D atlasDirectBack;

layout(std430, binding = BIND_SSBO_ATLAS_SENDER_ROWS) buffer SenderRows {
    float rowPower[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SENDER_BLOCKS) buffer SenderBlocks {
    float blockPower[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SENDER_POOL) buffer SenderPool {
    uint pool[];
};

// Texels whose radiance overflowed the half-float layer (inf) are never drawn: one of them
// would make every sum infinite.
float senderPower(int x, int y) {
    ivec2 t = ivec2(x, y);
    vec4 direct = texelFetch(atlasDirect, t, 0);
    if (direct.a <= 0.0) return 0.0;
    vec3 radiance = direct.rgb;
    if (texelFetch(atlasNormal, t, 0).w > 0.5) radiance += texelFetch(atlasDirectBack, t, 0).rgb;
    float power = max(texelFetch(atlasPosition, t, 0).w, 0.0) * dot(radiance, vec3(1.0 / 3.0));
    return isinf(power) || isnan(power) ? 0.0 : power;
}

int blocksPerRow(int resolution) {
    return (resolution + ATLAS_SENDER_BLOCK - 1) / ATLAS_SENDER_BLOCK;
}

#if defined(STEP_ROWS)

void main() {
    int y = int(gl_GlobalInvocationID.x);
    int resolution = atlas.size.x;
    if (y >= resolution) return;
    int blocks = blocksPerRow(resolution);
    float sum = 0.0;
    for (int b = 0; b < blocks; ++b) {
        int end = min(resolution, (b + 1) * ATLAS_SENDER_BLOCK);
        for (int x = b * ATLAS_SENDER_BLOCK; x < end; ++x) sum += senderPower(x, y);
        blockPower[y * blocks + b] = sum;
    }
    rowPower[y] = sum;
}

#elif defined(STEP_PREFIX)

void main() {
    if (gl_GlobalInvocationID.x != 0u) return;
    float sum = 0.0;
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
    float total = rowPower[resolution - 1];
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
        if (rowPower[mid] > target) hi = mid;
        else lo = mid + 1;
    }
    int y = lo;
    // A target rounded up to the total lands past the last row with area: step back to it.
    while (y > 0 && !(rowPower[y] > rowPower[y - 1])) --y;
    int blocks = blocksPerRow(resolution);
    int base = y * blocks;
    float rest = target - (y > 0 ? rowPower[y - 1] : 0.0);
    // The first block of the row whose prefix sum exceeds the rest.
    lo = 0;
    hi = blocks - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (blockPower[base + mid] > rest) hi = mid;
        else lo = mid + 1;
    }
    // Scan from that block to the texel that takes the sum past the rest. Rounding of the
    // prefix sums can leave the rest at or past the row's sum: then the row's last texel with
    // area is the sender.
    float sum = lo > 0 ? blockPower[base + lo - 1] : 0.0;
    int chosen = -1, last = -1;
    for (int x = lo * ATLAS_SENDER_BLOCK; x < resolution && chosen < 0; ++x) {
        float a = senderPower(x, y);
        if (a <= 0.0) continue;
        last = x;
        sum += a;
        if (sum > rest) chosen = x;
    }
    for (int x = lo * ATLAS_SENDER_BLOCK - 1; x >= 0 && last < 0; --x) {
        if (senderPower(x, y) > 0.0) last = x;
    }
    if (chosen < 0) chosen = last;
    pool[j] = chosen < 0 ? ~0u : uint(y * resolution + chosen);
}

#endif
