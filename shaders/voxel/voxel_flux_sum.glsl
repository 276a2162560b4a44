// The flux light injection adds to each voxel (INJECT_AREA), summed in fixed point with
// integer atomics: an integer sum is the same whatever order the fragments arrive in, so the
// voxels' light, and every image traced from it, is the same from run to run and on every
// driver. (A float sum under a lock rounds after each addition and depends on that order.)
// Each fragment's share is rounded to whole units stochastically, with a dither seeded by its
// pixel and light view, not by the order: unbiased in expectation at any magnitude.
// fluxSum.x, units per unit of flux / face area, is chosen on the CPU (fluxSumScale,
// InjectPass.h) so that no voxel's sum can reach 2^32.
#ifndef GI_VOXEL_FLUX_SUM_GLSL
#define GI_VOXEL_FLUX_SUM_GLSL

#include "../common/voxel_cascade.glsl"

layout(binding = BIND_IMG_VOXEL_FLUX_SUM, r32ui) uniform uimage3D voxelFluxSum;
layout(location = LOC_INJECT_FLUX_SUM) uniform vec2 fluxSum;

// Texel of channel c of the cascade texel `texel` (level slab included).
ivec3 fluxSumTexel(ivec3 texel, int c) {
    return texel + ivec3(c * voxelResolution(), 0, 0);
}

#ifdef VOXEL_FLUX_SUM_ADD
#include "voxel_lock.glsl"

// Adds `flux` (per unit of voxel face area) to the cascade texel `texel`.
void addToFluxSum(ivec3 texel, vec3 flux) {
    uint seed = (uint(gl_FragCoord.x) | (uint(gl_FragCoord.y) << 16u)) ^
            (uint(fluxSum.y) * 2654435761u);
    vec3 units = min(floor(flux * fluxSum.x + voxelRandom(seed)), vec3(2147483648.0));
    for (int c = 0; c < 3; ++c) {
        if (units[c] >= 1.0) imageAtomicAdd(voxelFluxSum, fluxSumTexel(texel, c), uint(units[c]));
    }
}
#endif

// The flux per unit of face area summed at `texel` (InjectPass clears the sums before
// injecting).
vec3 fluxSumAt(ivec3 texel) {
    vec3 sum;
    for (int c = 0; c < 3; ++c) sum[c] = float(imageLoad(voxelFluxSum, fluxSumTexel(texel, c)).r);
    return sum / fluxSum.x;
}

#endif
