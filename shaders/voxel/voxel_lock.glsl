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
#ifndef GI_VOXEL_LOCK_GLSL
#define GI_VOXEL_LOCK_GLSL

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
                BODY                                                               \
                memoryBarrierImage();                                              \
                waiting = false;                                                   \
                imageAtomicExchange(voxelLock, texel, (previous + 2u) & ~1u);      \
            }                                                                      \
        }                                                                          \
    }

#endif
