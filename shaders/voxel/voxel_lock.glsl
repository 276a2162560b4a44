// One spinlock per voxel guarding a running average (thesis Listing 4.2). The lock texel
// holds the lock in bit 0 and the number of values averaged so far in bits 1..31, so the
// count never saturates (a half-float count stops at 2048) and needs no extra texture.
//
// Why this cannot deadlock: the loop is the thesis' pattern, where the invocation that wins
// the lock runs its whole critical section and releases the lock inside the same iteration
// of the loop. Invocations that execute in lockstep (a SIMD group on llvmpipe or a GPU
// warp) therefore never wait on a lock held by a lane that cannot make progress: the
// holder's lane is active in the very branch that releases it. Each iteration some lane
// wins, so every lane finishes after at most as many iterations as there are lanes
// contending for the same voxel.
//
// Running averages and sums stored in RGBA16F / RGBA8_SNORM lose their small increments when
// the stored value is rounded (and llvmpipe truncates on store, which biases every update
// downwards: 2048 updates of a 0.5 average lose a quarter of it). Values are therefore
// rounded here, stochastically, to a value the format holds exactly: unbiased in
// expectation at any count, and exact whatever rounding mode the driver's store uses.
#ifndef GI_VOXEL_LOCK_GLSL
#define GI_VOXEL_LOCK_GLSL

// A uniform number in [0, 1) from a 32-bit seed (PCG hash, Jarzynski & Olano 2020).
float voxelRandom(uint seed) {
    uint state = seed * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return float((word >> 22u) ^ word) * (1.0 / 4294967296.0);
}

// x rounded up or down to a neighbouring half float with probability by distance.
vec4 roundToHalf(vec4 x, float u) {
    vec4 magnitude = abs(x);
    // Half floats: 10 mantissa bits; below 2^-14 the spacing is fixed at 2^-24.
    vec4 ulp = exp2(max(floor(log2(max(magnitude, vec4(1e-30)))), vec4(-14.0)) - 10.0);
    return sign(x) * min(floor(magnitude / ulp + u) * ulp, vec4(65504.0));
}

// x rounded up or down to a neighbouring 8-bit signed-normalised value.
vec4 roundToSnorm8(vec4 x, float u) {
    return floor(clamp(x, -1.0, 1.0) * 127.0 + u) / 127.0;
}

layout(binding = BIND_IMG_VOXEL_LOCK, r32ui) coherent uniform uimage3D voxelLock;

#define VOXEL_LOCKED_AVERAGE(texel, BODY)                                          \
    {                                                                              \
        bool waiting = true;                                                       \
        while (waiting) {                                                          \
            uint previous = imageAtomicOr(voxelLock, texel, 1u);                   \
            if ((previous & 1u) == 0u) {                                           \
                float count = float(previous >> 1u);                               \
                float keep = count / (count + 1.0);                                \
                float add = 1.0 / (count + 1.0);                                   \
                float dither = voxelRandom(previous ^ (uint(gl_FragCoord.x) << 16u) \
                                           ^ uint(gl_FragCoord.y) * 2654435761u);  \
                BODY                                                               \
                memoryBarrierImage();                                              \
                waiting = false;                                                   \
                imageAtomicExchange(voxelLock, texel, (previous + 2u) & ~1u);      \
            }                                                                      \
        }                                                                          \
    }

#endif
