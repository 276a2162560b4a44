// Visibility between a receiver and a sender through the voxel cascade's occupancy (SEEDS.md
// section 2, "future work: visibility"; the cascade layout of voxel_common.glsl, coverage in
// the albedo texture's alpha). The segment is marched in half-voxel steps of the finest level
// containing each point; every step multiplies the transmittance by 1 - coverage. Both ends
// first leave their own surface by one voxel along its normal, and the march stops half a
// voxel short of each end, so a surface never occludes itself. Parts of the segment outside
// the cascade count as empty.
#ifndef GI_ATLAS_VOXEL_VISIBILITY_GLSL
#define GI_ATLAS_VOXEL_VISIBILITY_GLSL

#include "../voxel/voxel_common.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelCoverage;

const int kMaxVisibilitySteps = 512;

float endOffset(vec3 p) {
    int level = finestLevel(p);
    return level >= 0 ? levelVoxelSize(level) : 0.0;
}

float voxelTransmittance(vec3 receiver, vec3 receiverNormal, vec3 sender, vec3 senderNormal) {
    float sizeA = endOffset(receiver), sizeB = endOffset(sender);
    vec3 a = receiver + receiverNormal * sizeA;
    vec3 b = sender + senderNormal * sizeB;
    vec3 d = b - a;
    float len = length(d);
    if (len <= 0.5 * (sizeA + sizeB)) return 1.0;
    vec3 dir = d / len;
    float t = 0.5 * sizeA;
    float end = len - 0.5 * sizeB;
    float transmittance = 1.0;
    float coarsest = levelVoxelSize(voxelLevels() - 1);
    for (int i = 0; i < kMaxVisibilitySteps && t < end && transmittance > 0.01; ++i) {
        vec3 p = a + dir * t;
        int level = finestLevel(p);
        if (level < 0) {
            t += 0.5 * coarsest;
            continue;
        }
        float coverage = texelFetch(voxelCoverage, voxelTexel(p, level), 0).a;
        transmittance *= 1.0 - clamp(coverage, 0.0, 1.0);
        t += 0.5 * levelVoxelSize(level);
    }
    return transmittance;
}

#endif
