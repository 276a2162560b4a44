// Line-space build, pass 1: marks the leaf voxels each shadow-casting triangle touches,
// conservatively (the triangle/box overlap test of Akenine-Moeller 2001), one group per
// triangle. The group's invocations share the voxel columns along the axis the triangle faces
// most; in each column only the few voxels its plane crosses are tested, so no invocation
// loops long (llvmpipe ends any shader loop after 65535 iterations).
#include "linespace_common.glsl"

layout(std430, binding = BIND_SSBO_LINESPACE_INPUT) readonly buffer TriangleBlock {
    vec4 corners[];
};

bool axisSeparates(vec3 axis, vec3 v0, vec3 v1, vec3 v2, vec3 halfSize) {
    float p0 = dot(v0, axis), p1 = dot(v1, axis), p2 = dot(v2, axis);
    float r = dot(halfSize, abs(axis));
    return min(p0, min(p1, p2)) > r || max(p0, max(p1, p2)) < -r;
}

// Whether the triangle (corners relative to the box centre) meets the box of half extent
// `halfSize`: no separating axis among the box's, the triangle's normal and the 9 edge
// crossings.
bool triangleMeetsBox(vec3 v0, vec3 v1, vec3 v2, vec3 halfSize) {
    vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
    bool apart = any(greaterThan(min(v0, min(v1, v2)), halfSize)) ||
                 any(lessThan(max(v0, max(v1, v2)), -halfSize)) ||
                 axisSeparates(cross(e0, e1), v0, v1, v2, halfSize);
    for (int i = 0; i < 3; ++i) {
        vec3 unit = vec3(i == 0, i == 1, i == 2);
        apart = apart || axisSeparates(cross(unit, e0), v0, v1, v2, halfSize) ||
                axisSeparates(cross(unit, e1), v0, v1, v2, halfSize) ||
                axisSeparates(cross(unit, e2), v0, v1, v2, halfSize);
    }
    return !apart;
}

void main() {
    uint t = flatGroup();
    if (t >= uint(corners.length()) / 3u) return;
    int depth = lineSpace.shape.y;
    uint r = levelResolution(depth);
    float leaf = lineSpace.root.w / float(r);
    vec3 a = (corners[3u * t].xyz - lineSpace.root.xyz) / leaf;
    vec3 b = (corners[3u * t + 1u].xyz - lineSpace.root.xyz) / leaf;
    vec3 c = (corners[3u * t + 2u].xyz - lineSpace.root.xyz) / leaf;
    vec3 lowest = min(a, min(b, c)), highest = max(a, max(b, c));
    ivec3 lo = clamp(ivec3(floor(lowest)), ivec3(0), ivec3(r - 1u));
    ivec3 hi = clamp(ivec3(floor(highest)), ivec3(0), ivec3(r - 1u));
    vec3 normal = cross(b - a, c - a);
    vec3 size = abs(normal);
    int w = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    int u = (w + 1) % 3, v = (w + 2) % 3;
    uint offset = levelOffset(depth);
    // A hair over half a voxel: a triangle on a voxel face marks the voxels on both sides.
    vec3 halfSize = vec3(0.5 + 1e-4);
    int columnsU = hi[u] - lo[u] + 1;
    int columns = columnsU * (hi[v] - lo[v] + 1);
    for (int k = int(gl_LocalInvocationID.x); k < columns; k += LINESPACE_LOCAL_SIZE) {
        ivec3 cell = ivec3(0);
        cell[u] = lo[u] + k % columnsU;
        cell[v] = lo[v] + k / columnsU;
        // The plane's w over the column's square, from its corners, within the triangle's.
        float wLo = highest[w], wHi = lowest[w];
        for (int corner = 0; corner < 4; ++corner) {
            vec3 p = vec3(0.0);
            p[u] = float(cell[u] + (corner & 1));
            p[v] = float(cell[v] + (corner >> 1));
            float along = a[w] - (normal[u] * (p[u] - a[u]) + normal[v] * (p[v] - a[v])) / normal[w];
            wLo = min(wLo, along);
            wHi = max(wHi, along);
        }
        int first = max(int(floor(max(wLo, lowest[w]) - 1e-3)), lo[w]);
        int last = min(int(floor(min(wHi, highest[w]) + 1e-3)), hi[w]);
        for (int along = first; along <= last; ++along) {
            cell[w] = along;
            vec3 centre = vec3(cell) + 0.5;
            if (triangleMeetsBox(a - centre, b - centre, c - centre, halfSize)) {
                markOccupied(offset, r, uvec3(cell));
            }
        }
    }
}
