// Shadow rays through the line spaces of an N-tree (render/LineSpaceShadows.h), Alg. 1 of Keul,
// Klee, Mueller, "Soft shadow computation using precomputed line space visibility
// information": at a node the ray's shaft (the sub-faces where its line enters and leaves the
// node) is looked up; an empty shaft means nothing in the node can block the ray, so the node
// is skipped; a non-empty one in a node one level above the leaves reports the ray occluded
// (the approximation: the shaft, not the ray, meets a non-empty leaf voxel); higher up the
// walk descends into the non-empty children along the ray, front to back.
// A node the segment does not cross from face to face (it starts or ends inside) cannot be
// judged by its shaft: the paper skips the node the ray starts in. Its empty shaft still
// proves the part inside empty, so above the deepest inner level such a node is descended
// into, and at that level it is skipped. Both ends are thus skipped at the deepest inner
// level (the end lies on an area light, or a point light sits in free space).
#ifndef GI_LINESPACE_GLSL
#define GI_LINESPACE_GLSL

#include "linespace_shafts.glsl"
#include "shared.h"

layout(std430, binding = BIND_SSBO_LINESPACE_NODES) readonly buffer LineSpaceNodeBlock {
    GpuLineSpaceHeader lineSpace;
    uint lineSpaceChildren[];
};

layout(std430, binding = BIND_SSBO_LINESPACE_BITS) readonly buffer LineSpaceBitBlock {
    uint lineSpaceBits[];
};

const int kLineSpaceMaxDepth = 4;
const int kLineSpaceSkip = 0;
const int kLineSpaceOccluded = 1;
const int kLineSpaceDescend = 2;

float lineSpaceLeafSize() {
    return lineSpace.root.w / pow(float(lineSpace.shape.x), float(lineSpace.shape.y));
}

// How far shadow rays keep off the surfaces at their ends: conservative voxelization marks
// voxels up to sqrt(3) voxel edges from a surface, and a ray through such a voxel of its own
// receiver (or of the wall an area light is mounted on) would find itself occluded.
float lineSpaceSurfaceClearance() {
    return 2.0 * lineSpaceLeafSize();
}

// What Alg. 1 does at `node` (lowest corner `lo`, edge `size`, at `level`); [tIn, tOut] is
// where the ray's line crosses the node.
int lineSpaceClassify(uint node, vec3 lo, float size, int level, vec3 origin, vec3 dir,
        vec3 inverseDir, float tMax, out float tIn, out float tOut) {
    vec3 t0 = (lo - origin) * inverseDir, t1 = (lo + size - origin) * inverseDir;
    vec3 near = min(t0, t1), far = max(t0, t1);
    tIn = max(max(near.x, near.y), near.z);
    tOut = min(min(far.x, far.y), far.z);
    if (!(tIn < tOut) || tOut <= 0.0 || tIn >= tMax) return kLineSpaceSkip;
    int entryAxis = near.x >= near.y && near.x >= near.z ? 0 : (near.y >= near.z ? 1 : 2);
    int exitAxis = far.x <= far.y && far.x <= far.z ? 0 : (far.y <= far.z ? 1 : 2);
    int entryFace = 2 * entryAxis + (dir[entryAxis] > 0.0 ? 0 : 1);
    int exitFace = 2 * exitAxis + (dir[exitAxis] > 0.0 ? 1 : 0);
    if (entryFace == exitFace) return kLineSpaceSkip;
    int n = lineSpace.shape.x;
    float scale = float(n) / size;
    uint entry = lineSpaceSubFace(entryAxis, (origin + dir * tIn - lo) * scale, n);
    uint exit = lineSpaceSubFace(exitAxis, (origin + dir * tOut - lo) * scale, n);
    uint shaft = lineSpaceShaftIndex(entryFace, entry, exitFace, exit, n);
    uint word = lineSpaceBits[node * uint(lineSpace.shape.z) + (shaft >> 5)];
    if (((word >> (shaft & 31u)) & 1u) == 0u) return kLineSpaceSkip;
    if (level < lineSpace.shape.y - 1) return kLineSpaceDescend;
    return tIn >= 0.0 && tOut <= tMax ? kLineSpaceOccluded : kLineSpaceSkip;
}

// Whether the line space reports the segment origin + t dir, 0 < t < tMax, blocked.
bool lineSpaceOccluded(vec3 origin, vec3 dir, float tMax) {
    if (lineSpace.shape.w == 0) return false;
    int n = lineSpace.shape.x;
    vec3 safe = mix(dir, vec3(1e-20), lessThan(abs(dir), vec3(1e-20)));
    vec3 inverseDir = 1.0 / safe;
    ivec3 stepDir = ivec3(greaterThan(dir, vec3(0.0))) * 2 - 1;
    vec3 upper = vec3(greaterThan(dir, vec3(0.0)));

    // One walk over the children of the node at each level: the node, its corner and child
    // edge, the child being visited, where the ray reaches the next child boundary per axis,
    // and where the ray leaves the node.
    uint walkNode[kLineSpaceMaxDepth];
    vec3 walkLo[kLineSpaceMaxDepth];
    float walkCell[kLineSpaceMaxDepth];
    ivec3 walkChild[kLineSpaceMaxDepth];
    vec3 walkNext[kLineSpaceMaxDepth];
    float walkAt[kLineSpaceMaxDepth];
    float walkEnd[kLineSpaceMaxDepth];

    float tIn, tOut;
    vec3 lo = lineSpace.root.xyz;
    float size = lineSpace.root.w;
    int verdict = lineSpaceClassify(0u, lo, size, 0, origin, dir, inverseDir, tMax, tIn, tOut);
    if (verdict != kLineSpaceDescend) return verdict == kLineSpaceOccluded;
    uint node = 0u;
    int level = 0;
    for (;;) {
        if (verdict == kLineSpaceDescend) {
            float cell = size / float(n);
            float start = max(tIn, 0.0);
            vec3 p = origin + dir * start;
            ivec3 child = clamp(ivec3(floor((p - lo) / cell)), ivec3(0), ivec3(n - 1));
            walkNode[level] = node;
            walkLo[level] = lo;
            walkCell[level] = cell;
            walkChild[level] = child;
            walkNext[level] = (lo + (vec3(child) + upper) * cell - origin) * inverseDir;
            walkAt[level] = start;
            walkEnd[level] = min(tOut, tMax);
        }
        ivec3 child = walkChild[level];
        if (any(lessThan(child, ivec3(0))) || any(greaterThanEqual(child, ivec3(n))) ||
                walkAt[level] >= walkEnd[level]) {
            if (--level < 0) return false;
            verdict = kLineSpaceSkip;
            continue;
        }
        vec3 next = walkNext[level];
        int axis = next.x <= next.y && next.x <= next.z ? 0 : (next.y <= next.z ? 1 : 2);
        walkAt[level] = next[axis];
        walkChild[level][axis] += stepDir[axis];
        walkNext[level][axis] += walkCell[level] * abs(inverseDir[axis]);
        uint slot = walkNode[level] * uint(n * n * n) + uint(child.x + n * (child.y + n * child.z));
        uint target = lineSpaceChildren[slot];
        verdict = kLineSpaceSkip;
        if (target == LINESPACE_EMPTY) continue;
        lo = walkLo[level] + vec3(child) * walkCell[level];
        size = walkCell[level];
        verdict = lineSpaceClassify(target, lo, size, level + 1, origin, dir, inverseDir, tMax, tIn, tOut);
        if (verdict == kLineSpaceOccluded) return true;
        if (verdict == kLineSpaceDescend) {
            node = target;
            ++level;
        }
    }
    return false;
}

#endif
