// Rays through the scene's bounding volume hierarchy (reference/GpuBvh.h: two children per
// node, flattened depth first, so the left child of node i is i + 1), for shadow rays: the
// walk stops at the first triangle hit. Triangles block from both sides.
#ifndef GI_BVH_GLSL
#define GI_BVH_GLSL

#include "shared.h"

layout(std430, binding = BIND_SSBO_BVH_NODES) readonly buffer BvhNodeBlock {
    vec4 bvhNodes[];
};

layout(std430, binding = BIND_SSBO_BVH_TRIANGLES) readonly buffer BvhTriangleBlock {
    vec4 bvhTriangles[];
};

// Deeper than any tree the builder makes (its depth is capped at 48).
const int kBvhStackSize = 64;

bool rayMeetsBox(vec3 origin, vec3 inverseDir, float tMax, vec3 lo, vec3 hi) {
    vec3 t0 = (lo - origin) * inverseDir, t1 = (hi - origin) * inverseDir;
    vec3 near = min(t0, t1), far = max(t0, t1);
    float enter = max(max(near.x, near.y), max(near.z, 0.0));
    float leave = min(min(far.x, far.y), min(far.z, tMax));
    return enter <= leave;
}

// Moeller-Trumbore, without culling: whether the ray meets the triangle at 0 < t < tMax.
bool rayMeetsTriangle(vec3 origin, vec3 dir, float tMax, vec3 a, vec3 b, vec3 c) {
    vec3 e1 = b - a, e2 = c - a;
    vec3 p = cross(dir, e2);
    float det = dot(e1, p);
    if (abs(det) < 1e-20) return false;
    float inverse = 1.0 / det;
    vec3 s = origin - a;
    float u = dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(dir, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return false;
    float t = dot(e2, q) * inverse;
    return t > 0.0 && t < tMax;
}

// Whether anything lies on the segment origin + t dir, 0 < t < tMax (dir of unit length).
bool bvhOccluded(vec3 origin, vec3 dir, float tMax) {
    // Components of exactly zero would give 0 x inf = NaN in the slab test.
    vec3 safe = mix(dir, vec3(1e-20), lessThan(abs(dir), vec3(1e-20)));
    vec3 inverseDir = 1.0 / safe;
    int stack[kBvhStackSize];
    int top = 0;
    int node = 0;
    for (;;) {
        vec4 lo = bvhNodes[2 * node], hi = bvhNodes[2 * node + 1];
        if (rayMeetsBox(origin, inverseDir, tMax, lo.xyz, hi.xyz)) {
            int link = floatBitsToInt(lo.w);
            if (link > 0) {
                // Inner node: the left child next, the right one (index `link`) later.
                if (top < kBvhStackSize) stack[top++] = link;
                node = node + 1;
                continue;
            }
            int first = floatBitsToInt(hi.w);
            for (int i = 0; i < -link; ++i) {
                int t = 3 * (first + i);
                if (rayMeetsTriangle(origin, dir, tMax, bvhTriangles[t].xyz, bvhTriangles[t + 1].xyz,
                        bvhTriangles[t + 2].xyz)) {
                    return true;
                }
            }
        }
        if (top == 0) return false;
        node = stack[--top];
    }
    return false;
}

#endif
