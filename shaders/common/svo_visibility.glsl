// Visibility between a receiver and a VPL through the sparse voxel octree (gi/vpl,
// vpl.visibility=svo): the seed's "SVO-restart" march (SEEDS.md section 4; Sun and Agu 2015,
// Fig. 3, after the kd-restart traversal of Foley and Sugerman 2005). Each step descends from
// the root to the deepest node that holds the current point: an occupied leaf blocks the
// segment; an empty node is skipped to where the segment leaves its cube plus an epsilon, and
// the next step restarts from the root. Both ends lie in occupied leaves, their own surfaces:
// each first leaves its surface along its normal (svo.march.x leaf voxels) and the segment is
// then shrunk at both ends (svo.march.y), so a surface does not occlude itself. The epsilon
// (svo.march.z) keeps a step from stopping on the face it exits through. Parts of the segment
// outside the octree's cube are empty. Visibility is binary, as in the paper.
#ifndef GI_SVO_VISIBILITY_GLSL
#define GI_SVO_VISIBILITY_GLSL

#include "svo.glsl"

// SVO_VISIBILITY_MAX_STEPS: more steps than any segment through a 1024^3 octree takes between
// occupied leaves' empty neighbours; a segment that runs out of steps counts as unblocked. Each
// step descends at most depth + 1 levels: SparseVoxelOctree::visibilityLoopIterations.

float svoMin3(vec3 v) { return min(v.x, min(v.y, v.z)); }
float svoMax3(vec3 v) { return max(v.x, max(v.y, v.z)); }

// Distance along the ray a + t dir (invDir = 1 / dir) to where it leaves [lo, lo + size]^3.
float svoExitDistance(vec3 a, vec3 invDir, vec3 lo, float size) {
    vec3 bound = mix(lo, lo + size, greaterThan(invDir, vec3(0.0)));
    return svoMin3((bound - a) * invDir);
}

// 0 if an occupied leaf lies on the segment a -> b (leaf voxels), else 1.
float svoSegmentVisibility(vec3 a, vec3 b) {
    vec3 d = b - a;
    float len = length(d);
    if (len <= 2.0 * svo.march.y) return 1.0;
    vec3 dir = d / len;
    // A zero component would divide by zero; a tiny positive one never exits on that axis.
    vec3 invDir = 1.0 / mix(dir, vec3(1e-12), lessThan(abs(dir), vec3(1e-12)));
    float r = float(svoResolution());
    vec3 t0 = -a * invDir, t1 = (vec3(r) - a) * invDir;
    float t = max(svoMax3(min(t0, t1)), svo.march.y);
    float tEnd = min(svoMin3(max(t0, t1)), len - svo.march.y);
    int depth = svoDepth();
    for (int step = 0; step < SVO_VISIBILITY_MAX_STEPS && t < tEnd; ++step) {
        vec3 p = a + dir * t;
        uint node = 0u;
        vec3 lo = vec3(0.0);
        float size = r;
        for (int level = 0; level <= depth; ++level) {
            uint word = svoNodes[node];
            if ((word & SVO_NODE_FLAG) == 0u) break;
            if (level == depth) return 0.0;
            size *= 0.5;
            uvec3 octant = uvec3(greaterThanEqual(p, lo + size));
            lo += vec3(octant) * size;
            node = (word & SVO_CHILD_MASK) + svoChildSlot(octant);
        }
        t = max(svoExitDistance(a, invDir, lo, size), t) + svo.march.z;
    }
    return 1.0;
}

float svoVisibility(vec3 receiver, vec3 receiverNormal, vec3 light, vec3 lightNormal) {
    vec3 a = svoFromWorld(receiver) + receiverNormal * svo.march.x;
    vec3 b = svoFromWorld(light) + lightNormal * svo.march.x;
    return svoSegmentVisibility(a, b);
}

#endif
