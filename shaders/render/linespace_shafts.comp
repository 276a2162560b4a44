// Line-space build, pass 3: the bits of every node's line space, one uint (32 shafts) per
// invocation, the groups of one node in a row (short loops: llvmpipe ends any shader loop
// after 65535 iterations). A
// shaft's bit is set when the shaft meets a non-empty child. The test is exact for the
// shaft as a solid: the segments from sub-face A to sub-face B sweep, at parameter t, the box
// (1 - t) A + t B (a Minkowski sum of axis-aligned rectangles), so the shaft meets a child
// exactly when some t in [0, 1] has that box overlapping the child on all three axes, each
// axis a linear condition on t. Overlaps thinner than 1e-4 child edges do not count, so a
// shaft that only touches a child's face leaves the child out.
#include "linespace_common.glsl"
#include "../common/linespace_shafts.glsl"

layout(std430, binding = BIND_SSBO_LINESPACE_INPUT) readonly buffer NodeCellBlock {
    uvec4 nodeCells[];   // x = level, yzw = the node's cell on its level
};

layout(std430, binding = BIND_SSBO_LINESPACE_BITS) writeonly buffer LineSpaceBitBlock {
    uint lineSpaceBits[];
};

const float kTouch = 1e-4;

// Per column (cx, cy) of the node's children, bit cz set when that child is occupied.
shared uint columns[100];

// The t in [0, 1] where a0 + t (a1 - a0) < bound (below) or > bound (!below).
vec2 linearInterval(float a0, float a1, float bound, bool below) {
    float slope = a1 - a0;
    if (abs(slope) < 1e-12) return (below ? a0 < bound : a0 > bound) ? vec2(0.0, 1.0) : vec2(1.0, 0.0);
    float at = (bound - a0) / slope;
    bool lower = (slope > 0.0) == below;
    return lower ? vec2(0.0, min(at, 1.0)) : vec2(max(at, 0.0), 1.0);
}

vec2 overlap(vec2 a, vec2 b) {
    return vec2(max(a.x, b.x), min(a.y, b.y));
}

// The t where the shaft's cross-section overlaps child cell c along `axis`.
vec2 cellInterval(vec3 loA, vec3 hiA, vec3 loB, vec3 hiB, int axis, int c) {
    vec2 t = linearInterval(loA[axis], loB[axis], float(c + 1) - kTouch, true);
    return overlap(t, linearInterval(hiA[axis], hiB[axis], float(c) + kTouch, false));
}

void subFaceRect(int face, uint sub, int n, out vec3 lo, out vec3 hi) {
    int axis = face / 2;
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    lo = vec3(0.0);
    lo[axis] = float((face & 1) * n);
    lo[u] = float(int(sub) % n);
    lo[v] = float(int(sub) / n);
    hi = lo + vec3(1.0);
    hi[axis] = lo[axis];
}

bool shaftMeetsChildren(uint shaft, int n) {
    uint faces = uint(n * n);
    uint pair = shaft / (faces * faces);
    uint within = shaft % (faces * faces);
    int fa = 0;
    while (pair >= uint(5 - fa)) {
        pair -= uint(5 - fa);
        ++fa;
    }
    int fb = fa + 1 + int(pair);
    vec3 loA, hiA, loB, hiB;
    subFaceRect(fa, within / faces, n, loA, hiA);
    subFaceRect(fb, within % faces, n, loB, hiB);
    for (int cx = 0; cx < n; ++cx) {
        vec2 tx = cellInterval(loA, hiA, loB, hiB, 0, cx);
        if (tx.x > tx.y) continue;
        for (int cy = 0; cy < n; ++cy) {
            vec2 t = overlap(tx, cellInterval(loA, hiA, loB, hiB, 1, cy));
            if (t.x > t.y || columns[cx + n * cy] == 0u) continue;
            // Over t the z extent sweeps an interval: the lows' and highs' extremes lie at the
            // ends of t.
            float zLo = min(mix(loA.z, loB.z, t.x), mix(loA.z, loB.z, t.y));
            float zHi = max(mix(hiA.z, hiB.z, t.x), mix(hiA.z, hiB.z, t.y));
            int z0 = max(int(floor(zLo + kTouch)), 0);
            int z1 = min(int(ceil(zHi - kTouch)) - 1, n - 1);
            if (z0 > z1) continue;
            uint range = ((2u << uint(z1)) - 1u) & ~((1u << uint(z0)) - 1u);
            if ((columns[cx + n * cy] & range) != 0u) return true;
        }
    }
    return false;
}

void main() {
    uint words = uint(lineSpace.shape.z);
    uint groupsPerNode = (words + uint(LINESPACE_LOCAL_SIZE) - 1u) / uint(LINESPACE_LOCAL_SIZE);
    uint node = flatGroup() / groupsPerNode;
    if (node >= uint(lineSpace.shape.w)) return;
    int n = lineSpace.shape.x;
    uvec4 info = nodeCells[node];
    int childLevel = int(info.x) + 1;
    uint childOffset = levelOffset(childLevel);
    uint rc = levelResolution(childLevel);
    for (uint i = gl_LocalInvocationID.x; i < uint(n * n); i += uint(LINESPACE_LOCAL_SIZE)) {
        uint column = 0u;
        for (int z = 0; z < n; ++z) {
            uvec3 child = info.yzw * uint(n) + uvec3(i % uint(n), i / uint(n), uint(z));
            if (occupied(childOffset, rc, child)) column |= 1u << uint(z);
        }
        columns[i] = column;
    }
    barrier();
    uint w = (flatGroup() % groupsPerNode) * uint(LINESPACE_LOCAL_SIZE) + gl_LocalInvocationID.x;
    if (w >= words) return;
    uint shafts = 15u * uint(n * n) * uint(n * n);
    uint bits = 0u;
    for (uint b = 0u; b < 32u; ++b) {
        uint shaft = w * 32u + b;
        bool meets = shaft < shafts && shaftMeetsChildren(shaft, n);
        if (meets) bits |= 1u << b;
    }
    lineSpaceBits[node * words + w] = bits;
}
