// Rays through the scene's bounding volume hierarchy (reference/GpuBvh.h: two children per
// node, flattened depth first, so the left child of node i is i + 1): shadow rays, whose walk
// stops at the first triangle hit, and the nearest hit along a short segment. Triangles block
// from both sides.
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

// Moeller-Trumbore, without culling: (t, u, v) where the ray meets the triangle at
// 0 < t < tMax (u and v the weights of corners b and c), t = -1 where it does not.
vec3 rayTriangleHit(vec3 origin, vec3 dir, float tMax, vec3 a, vec3 b, vec3 c) {
    const vec3 miss = vec3(-1.0, 0.0, 0.0);
    vec3 e1 = b - a, e2 = c - a;
    vec3 p = cross(dir, e2);
    float det = dot(e1, p);
    if (abs(det) < 1e-20) return miss;
    float inverse = 1.0 / det;
    vec3 s = origin - a;
    float u = dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return miss;
    vec3 q = cross(s, e1);
    float v = dot(dir, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return miss;
    float t = dot(e2, q) * inverse;
    return t > 0.0 && t < tMax ? vec3(t, u, v) : miss;
}

// The walk of both queries: the triangles the segment origin + t dir, 0 < t < tMax, meets (dir
// of unit length). `nearest`: the nearest of them, the segment shortened at each hit; else the
// first found. At most maxNodes nodes are visited (a walk cut short reports what it found).
// Returns (t, u, v) of the hit, t = -1 for none, and the hit triangle's first corner in
// `corner` (bvhTriangles[corner].w: the triangle's index in the scene's order, as int bits).
vec3 bvhWalk(vec3 origin, vec3 dir, float tMax, bool nearest, int maxNodes, out int corner) {
    // Components of exactly zero would give 0 x inf = NaN in the slab test.
    vec3 safe = mix(dir, vec3(1e-20), lessThan(abs(dir), vec3(1e-20)));
    vec3 inverseDir = 1.0 / safe;
    int stack[kBvhStackSize];
    int top = 0;
    int node = 0;
    vec3 hit = vec3(-1.0, 0.0, 0.0);
    corner = -1;
    for (int visited = 0; visited < maxNodes; ++visited) {
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
                vec3 h = rayTriangleHit(origin, dir, tMax, bvhTriangles[t].xyz,
                        bvhTriangles[t + 1].xyz, bvhTriangles[t + 2].xyz);
                if (h.x > 0.0) {
                    hit = h;
                    corner = t;
                    if (!nearest) return hit;
                    tMax = h.x;
                }
            }
        }
        if (top == 0) break;
        node = stack[--top];
    }
    return hit;
}

// Whether anything lies on the segment origin + t dir, 0 < t < tMax (dir of unit length).
bool bvhOccluded(vec3 origin, vec3 dir, float tMax) {
    int corner;
    return bvhWalk(origin, dir, tMax, false, 0x7fffffff, corner).x > 0.0;
}

#endif
