// Visibility between a shading point and a VPL, one rule per vpl.visibility, chosen when the
// gather is compiled (VPL_VISIBILITY = VPL_VISIBILITY_*).
#ifndef GI_VPL_VISIBILITY_GLSL
#define GI_VPL_VISIBILITY_GLSL

#include "../common/shared.h"

#if VPL_VISIBILITY == VPL_VISIBILITY_CASCADE
#include "../common/voxel_visibility.glsl"
#elif VPL_VISIBILITY == VPL_VISIBILITY_SVO
#include "../common/svo_visibility.glsl"
#elif VPL_VISIBILITY == VPL_VISIBILITY_BVH
#include "../common/bvh.glsl"
#endif

float vplVisibility(vec3 receiver, vec3 receiverNormal, vec3 light, vec3 lightNormal) {
#if VPL_VISIBILITY == VPL_VISIBILITY_CASCADE
    return voxelTransmittance(receiver, receiverNormal, light, lightNormal);
#elif VPL_VISIBILITY == VPL_VISIBILITY_SVO
    return svoVisibility(receiver, receiverNormal, light, lightNormal);
#elif VPL_VISIBILITY == VPL_VISIBILITY_BVH
    // One ray, both ends pushed off their surfaces as shadow rays are (1e-4 of the scene).
    vec3 a = receiver + receiverNormal * vpl.rays.x;
    vec3 d = light + lightNormal * vpl.rays.x - a;
    float len = length(d);
    return len > 0.0 && bvhOccluded(a, d / len, len * (1.0 - 1e-4)) ? 0.0 : 1.0;
#else
    return 1.0;
#endif
}

#endif
