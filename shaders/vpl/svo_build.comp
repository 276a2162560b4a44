// The octree's top-down build (Crassin and Green 2012, without recursion), one of three
// passes per level, chosen when compiled (SVO_PASS = SVO_PASS_*), the level in `level`:
//   flag     : each occupied leaf of the fragment list walks down from the root through the
//              children the levels above allocated and flags its node at `level`;
//   allocate : each flagged node of `level` takes 8 consecutive nodes from the atomic
//              counter, clears them and points at them (a pool too small sets the overflow
//              flag and leaves the node childless);
//   advance  : one invocation writes where `level + 1` ends and the indirect dispatch that
//              allocates it.
// The leaves' level is flagged only. Nodes of a level are consecutive, allocated in order.
#define SVO_BUILD
#include "../common/svo.glsl"

layout(local_size_x = SVO_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_SVO_FRAGMENTS) readonly buffer SvoFragmentBlock {
    uint fragmentCount;
    uint fragments[];
};

layout(std430, binding = BIND_SSBO_SVO_BUILD) coherent buffer SvoBuildBlock {
    SvoBuildState build;
};

layout(location = LOC_SVO_LEVEL) uniform int level;

#if SVO_PASS == SVO_PASS_FLAG
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(fragmentCount, uint(fragments.length()))) return;
    uvec3 leaf = svoUnpackLeaf(fragments[i]);
    int depth = svoDepth();
    uint node = 0u;
    for (int l = 0; l < level; ++l) {
        uint children = svoNodes[node] & SVO_CHILD_MASK;
        if (children == 0u) return;   // the pool overflowed above
        node = children + svoChildSlot((leaf >> uint(depth - 1 - l)) & 1u);
    }
    // Every leaf below the node writes the same word, and the node has no children yet.
    svoNodes[node] = SVO_NODE_FLAG;
}
#elif SVO_PASS == SVO_PASS_ALLOCATE
void main() {
    int node = build.levelStart[level] + int(gl_GlobalInvocationID.x);
    if (node >= build.levelStart[level + 1] || (svoNodes[node] & SVO_NODE_FLAG) == 0u) return;
    int children = atomicAdd(build.counts.x, 8);
    if (children + 8 > svo.shape.w) {
        build.counts.y = 1;
        return;
    }
    for (int c = 0; c < 8; ++c) svoNodes[children + c] = 0u;
    svoNodes[node] = SVO_NODE_FLAG | uint(children);
}
#elif SVO_PASS == SVO_PASS_ADVANCE
void main() {
    int end = min(build.counts.x, svo.shape.w);
    build.levelStart[level + 2] = end;
    int count = max(end - build.levelStart[level + 1], 0);
    build.dispatch = ivec4((count + SVO_LOCAL_SIZE - 1) / SVO_LOCAL_SIZE, 1, 1, 0);
}
#endif
